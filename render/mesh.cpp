#include "render/mesh.h"

#include <GL/glext.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace tumble::render {

// --- Sphere ----------------------------------------------------------------------------------
// Vertex layout: the north pole, then rings-1 circles of `segments` vertices from north to
// south, then the south pole. On a unit sphere the normal is the position itself.
MeshData make_sphere(int segments, int rings) {
    MeshData m;
    const glm::vec3 north{0, 0, 1}, south{0, 0, -1};
    m.vertices.push_back({north, north});
    for (int r = 1; r < rings; ++r) {
        const float theta = glm::pi<float>() * float(r) / float(rings); // angle from north
        for (int s = 0; s < segments; ++s) {
            const float phi = glm::two_pi<float>() * float(s) / float(segments);
            const glm::vec3 p{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta)};
            m.vertices.push_back({p, p});
        }
    }
    m.vertices.push_back({south, south});

    // Index of vertex s on circle r (1..rings-1); s wraps around so the seam closes.
    auto at = [segments](int r, int s) {
        return std::uint32_t(1 + (r - 1) * segments + (s % segments));
    };
    const auto south_index = std::uint32_t(m.vertices.size() - 1);
    auto tri = [&m](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        m.indices.insert(m.indices.end(), {a, b, c});
    };
    for (int s = 0; s < segments; ++s) {
        tri(0, at(1, s), at(1, s + 1)); // north cap: a fan around the pole
        for (int r = 1; r + 1 < rings; ++r) {
            // The quad between circle r (above) and r+1 (below), as two triangles.
            tri(at(r, s), at(r + 1, s), at(r + 1, s + 1));
            tri(at(r, s), at(r + 1, s + 1), at(r, s + 1));
        }
        tri(south_index, at(rings - 1, s + 1), at(rings - 1, s)); // south cap
    }
    return m;
}

// --- Box -------------------------------------------------------------------------------------
// Each face is the square n + a*u + b*v (a, b in {-1, 1}) where u x v = n, which makes the
// corner order (-,-), (+,-), (+,+), (-,+) counter-clockwise seen from outside.
MeshData make_box() {
    MeshData m;
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            glm::vec3 n{0.0f}, u{0.0f}, v{0.0f};
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (sign < 0) std::swap(u, v); // keeps u x v = n on the negative face
            const auto first = std::uint32_t(m.vertices.size());
            for (glm::vec2 c : {glm::vec2{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
                m.vertices.push_back({n + c.x * u + c.y * v, n});
            }
            m.indices.insert(m.indices.end(),
                             {first, first + 1, first + 2, first, first + 2, first + 3});
        }
    }
    return m;
}

// --- Plane -----------------------------------------------------------------------------------
MeshData make_plane(int cells) {
    MeshData m;
    const glm::vec3 up{0, 0, 1};
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i)
            m.vertices.push_back({{-1.0f + 2.0f * float(i) / float(cells),
                                   -1.0f + 2.0f * float(j) / float(cells), 0.0f},
                                  up});
    auto at = [cells](int i, int j) { return std::uint32_t(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i)
            m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                               at(i + 1, j + 1), at(i, j + 1)});
    return m;
}

// --- Cylinder --------------------------------------------------------------------------------
// The side: two circles of `segments` + 1 vertices (the seam vertex is repeated so each quad
// indexes its own neighbours), normals radial. Each cap: a centre vertex and a ring of its own
// with normal +-z, as a fan.
MeshData make_cylinder(int segments) {
    MeshData m;
    auto ring_point = [segments](int s) {
        const float phi = glm::two_pi<float>() * float(s % segments) / float(segments);
        return glm::vec2{std::cos(phi), std::sin(phi)};
    };
    for (int s = 0; s <= segments; ++s) {
        const glm::vec2 c = ring_point(s);
        const glm::vec3 n{c.x, c.y, 0.0f};
        m.vertices.push_back({{c.x, c.y, -1.0f}, n}); // 2s: bottom
        m.vertices.push_back({{c.x, c.y, 1.0f}, n});  // 2s + 1: top
    }
    for (int s = 0; s < segments; ++s) {
        const auto b0 = std::uint32_t(2 * s), t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
        m.indices.insert(m.indices.end(), {b0, b1, t1, b0, t1, t0});
    }
    for (float z : {1.0f, -1.0f}) {
        const glm::vec3 n{0.0f, 0.0f, z};
        const auto centre = std::uint32_t(m.vertices.size());
        m.vertices.push_back({n, n});
        for (int s = 0; s < segments; ++s) {
            const glm::vec2 c = ring_point(s);
            m.vertices.push_back({{c.x, c.y, z}, n});
        }
        for (int s = 0; s < segments; ++s) {
            const auto a = centre + 1 + std::uint32_t(s);
            const auto b = centre + 1 + std::uint32_t((s + 1) % segments);
            // Counter-clockwise seen from outside: from above on the top cap, from below on the
            // bottom one, where the ring's order runs the other way.
            if (z > 0)
                m.indices.insert(m.indices.end(), {centre, a, b});
            else
                m.indices.insert(m.indices.end(), {centre, b, a});
        }
    }
    return m;
}

MeshData make_mesh(MeshKind kind) {
    switch (kind) {
    case MeshKind::Sphere:
        return make_sphere();
    case MeshKind::Box:
        return make_box();
    case MeshKind::Plane:
        return make_plane();
    case MeshKind::Cylinder:
        return make_cylinder();
    case MeshKind::Custom:
        break;
    }
    throw std::invalid_argument("make_mesh: custom meshes come from SceneView::meshes");
}

// --- Custom meshes ---------------------------------------------------------------------------
MeshData flat_shaded_mesh(const std::vector<glm::vec3>& positions,
                          const std::vector<std::uint32_t>& triangle_indices) {
    if (triangle_indices.size() % 3 != 0)
        throw std::invalid_argument("flat_shaded_mesh: " + std::to_string(triangle_indices.size()) +
                                    " indices is not a whole number of triangles");
    MeshData m;
    m.vertices.reserve(triangle_indices.size());
    m.indices.reserve(triangle_indices.size());
    for (std::size_t i = 0; i < triangle_indices.size(); i += 3) {
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t index = triangle_indices[i + std::size_t(k)];
            if (index >= positions.size())
                throw std::invalid_argument("flat_shaded_mesh: triangle " + std::to_string(i / 3) +
                                            " uses vertex " + std::to_string(index) + " of " +
                                            std::to_string(positions.size()));
            p[k] = positions[index];
        }
        const glm::vec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float area2 = glm::length(face);
        if (!(area2 > 0.0f)) continue; // degenerate: no area, no normal
        const glm::vec3 n = face / area2;
        for (const glm::vec3& q : p) {
            m.indices.push_back(std::uint32_t(m.vertices.size()));
            m.vertices.push_back({q, n});
        }
    }
    return m;
}

// --- GPU upload ------------------------------------------------------------------------------
GpuMesh::GpuMesh(const MeshData& data) : index_count_(GLsizei(data.indices.size())) {
    for (const Vertex& v : data.vertices) {
        half_extent_ = glm::max(half_extent_, glm::abs(v.position));
        radius_ = std::max(radius_, glm::length(v.position));
    }
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glGenBuffers(1, &ebo_);
    glBindVertexArray(vao_); // the VAO records the buffer bindings and layouts below

    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.vertices.size() * sizeof(Vertex)),
                 data.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(data.indices.size() * sizeof(std::uint32_t)),
                 data.indices.data(), GL_STATIC_DRAW);

    // Attribute 0: position, attribute 1: normal; both 3 floats, interleaved in Vertex.
    const auto stride = GLsizei(sizeof(Vertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(Vertex, normal)));
    glBindVertexArray(0);
}

GpuMesh::~GpuMesh() {
    destroy();
}

GpuMesh::GpuMesh(GpuMesh&& other) noexcept
    : vao_(std::exchange(other.vao_, 0)), vbo_(std::exchange(other.vbo_, 0)),
      ebo_(std::exchange(other.ebo_, 0)), index_count_(std::exchange(other.index_count_, 0)),
      half_extent_(other.half_extent_), radius_(other.radius_) {}

GpuMesh& GpuMesh::operator=(GpuMesh&& other) noexcept {
    if (this != &other) {
        destroy();
        vao_ = std::exchange(other.vao_, 0);
        vbo_ = std::exchange(other.vbo_, 0);
        ebo_ = std::exchange(other.ebo_, 0);
        index_count_ = std::exchange(other.index_count_, 0);
        half_extent_ = other.half_extent_;
        radius_ = other.radius_;
    }
    return *this;
}

void GpuMesh::destroy() {
    if (vao_) glDeleteVertexArrays(1, &vao_);
    if (vbo_) glDeleteBuffers(1, &vbo_);
    if (ebo_) glDeleteBuffers(1, &ebo_);
    vao_ = vbo_ = ebo_ = 0;
}

void GpuMesh::bind() const {
    glBindVertexArray(vao_);
}

void GpuMesh::draw() const {
    glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

void GpuMesh::draw_instanced(GLsizei count) const {
    glDrawElementsInstanced(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr, count);
}

} // namespace tumble::render
