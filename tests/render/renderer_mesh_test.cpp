// The procedural meshes are what Instance::transform expects: unit size, outward normals,
// triangles wound counter-clockwise seen from outside.
#include "render/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace tumble::render {
namespace {

// Every triangle's geometric normal (b - a) x (c - a) points the same way as its vertex normals.
void expect_outward_ccw(const MeshData& m) {
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (std::size_t i = 0; i < m.indices.size(); i += 3) {
        for (int k = 0; k < 3; ++k) ASSERT_LT(m.indices[i + k], m.vertices.size());
        const Vertex& a = m.vertices[m.indices[i]];
        const Vertex& b = m.vertices[m.indices[i + 1]];
        const Vertex& c = m.vertices[m.indices[i + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        ASSERT_GT(glm::length(face), 0.0f) << "degenerate triangle " << i / 3;
        EXPECT_GT(glm::dot(face, a.normal + b.normal + c.normal), 0.0f) << "triangle " << i / 3;
    }
}

TEST(RendererMesh, SphereIsUnitWithSmoothNormals) {
    const MeshData m = make_sphere(16, 8);
    EXPECT_EQ(m.vertices.size(), 2u + 16u * 7u);
    EXPECT_EQ(m.indices.size(), 3u * 2u * 16u * 7u);
    for (const Vertex& v : m.vertices) {
        EXPECT_NEAR(glm::length(v.position), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(v.normal - v.position), 0.0f, 1e-5f);
    }
    expect_outward_ccw(m);
}

TEST(RendererMesh, BoxSpansMinusOneToOneWithFlatNormals) {
    const MeshData m = make_box();
    EXPECT_EQ(m.vertices.size(), 24u);
    EXPECT_EQ(m.indices.size(), 36u);
    for (const Vertex& v : m.vertices) {
        for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(std::abs(v.position[k]), 1.0f);
        EXPECT_FLOAT_EQ(glm::length(v.normal), 1.0f);
        EXPECT_FLOAT_EQ(glm::dot(v.normal, v.position), 1.0f); // on the face the normal names
    }
    expect_outward_ccw(m);
}

TEST(RendererMesh, PlaneIsUnitSquareGridFacingUp) {
    const MeshData m = make_plane(4);
    EXPECT_EQ(m.vertices.size(), 25u);
    EXPECT_EQ(m.indices.size(), 4u * 4u * 6u);
    int corners = 0;
    for (const Vertex& v : m.vertices) {
        EXPECT_EQ(v.position.z, 0.0f);
        EXPECT_LE(std::abs(v.position.x), 1.0f);
        EXPECT_LE(std::abs(v.position.y), 1.0f);
        EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
        corners += std::abs(v.position.x) == 1.0f && std::abs(v.position.y) == 1.0f;
    }
    EXPECT_EQ(corners, 4);
    expect_outward_ccw(m);
}

TEST(RendererMesh, CylinderIsUnitWithRadialSideAndFlatCaps) {
    const MeshData m = make_cylinder(12);
    int side = 0, caps = 0;
    for (const Vertex& v : m.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
        if (v.normal.z == 0.0f) { // side: on the unit circle, normal radial
            ++side;
            EXPECT_NEAR(std::hypot(v.position.x, v.position.y), 1.0f, 1e-6f);
            EXPECT_EQ(std::abs(v.position.z), 1.0f);
            EXPECT_NEAR(glm::length(v.normal - glm::vec3(v.position.x, v.position.y, 0)), 0.0f,
                        1e-6f);
        } else { // cap: on the plane z = +-1 its normal names, inside the unit disk
            ++caps;
            EXPECT_EQ(v.position.z, v.normal.z);
            EXPECT_LE(std::hypot(v.position.x, v.position.y), 1.0f + 1e-6f);
        }
    }
    EXPECT_EQ(side, 2 * 13);
    EXPECT_EQ(caps, 2 * 13);
    EXPECT_EQ(m.indices.size(), 3u * (2 * 12 + 2 * 12));
    expect_outward_ccw(m);
}

TEST(RendererMesh, FlatShadedMeshGivesEachTriangleItsFaceNormal) {
    // A tetrahedron, one face wound each way would be a bug in the file; here all are outward.
    const std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<std::uint32_t> tris{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 0, 1};
    const MeshData m = flat_shaded_mesh(p, tris); // the last triangle is degenerate: dropped
    EXPECT_EQ(m.vertices.size(), 12u);
    EXPECT_EQ(m.indices.size(), 12u);
    EXPECT_EQ(m.vertices[0].normal, glm::vec3(0, 0, -1));
    const float s = 1.0f / std::sqrt(3.0f);
    EXPECT_NEAR(glm::length(m.vertices[9].normal - glm::vec3(s, s, s)), 0.0f, 1e-6f);
    expect_outward_ccw(m);
    EXPECT_THROW(flat_shaded_mesh(p, {0, 1}), std::invalid_argument);
    EXPECT_THROW(flat_shaded_mesh(p, {0, 1, 4}), std::invalid_argument);
}

} // namespace
} // namespace tumble::render
