#pragma once
// Triangle meshes on the CPU, with no GL in sight: what the renderer uploads, and what the app
// builds for custom (OBJ) bodies. Conventions shared by all meshes:
//   - indexed triangles, wound counter-clockwise when seen from outside (front faces);
//   - one normal per vertex (unit length, pointing out of the surface);
//   - placed in the world by Instance::transform (scene_view.h).
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tumble::render {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

struct MeshData {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices; // three per triangle
};

// A mesh from bare triangles (as read from an OBJ file: positions, three indices per triangle),
// with flat shading: every triangle gets its own three vertices carrying its face normal, so
// the facets of a hull read as facets. Degenerate triangles (zero area) are dropped. Throws
// std::invalid_argument when an index is out of range or the count is not a multiple of 3.
MeshData flat_shaded_mesh(const std::vector<glm::vec3>& positions,
                          const std::vector<std::uint32_t>& triangle_indices);

} // namespace tumble::render
