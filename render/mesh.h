#pragma once
// Procedural meshes for each MeshKind, built once on the CPU (MeshData) and uploaded once to the
// GPU (GpuMesh). Conventions shared by all meshes are in mesh_data.h; in addition:
//   - normals are smooth on the sphere and the cylinder's side (the normal of the true surface at
//     that point), flat on the box and the cylinder's caps (a face has its own vertices so its
//     corners do not share normals);
//   - unit size, placed in the world by Instance::transform (see scene_view.h).
#include "render/mesh_data.h"
#include "render/scene_view.h"

#include <GL/gl.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tumble::render {

// Unit sphere (radius 1) as latitude/longitude bands around the z axis: `segments` around,
// `rings` from pole to pole. 64 x 32 looks round at 720p.
MeshData make_sphere(int segments = 64, int rings = 32);
MeshData make_box(); // [-1,1]^3, 24 vertices (4 per face), flat normals
// The square [-1,1]^2 at z = 0, normal +z, as a grid of cells x cells squares. One cell is the
// cheapest for llvmpipe (a few huge triangles rasterise faster than many; measured: 16 x 16
// cells cost 8-10 ms more per 720p frame with MSAA), so that is the default.
MeshData make_plane(int cells = 1);
// Unit cylinder: radius 1 around the z axis, z in [-1, 1], `segments` around, closed by two flat
// caps (their own vertices, normals +-z). A capsule is drawn as this plus two spheres.
MeshData make_cylinder(int segments = 48);
// The unit mesh of a built-in kind (not MeshKind::Custom, whose meshes come from the SceneView).
MeshData make_mesh(MeshKind kind);

// A mesh in GPU memory: vertex buffer + index buffer, described by a vertex array object
// (attribute 0 = position, attribute 1 = normal). Move-only; needs a current GL context.
class GpuMesh {
  public:
    GpuMesh() = default;
    explicit GpuMesh(const MeshData& data);
    ~GpuMesh();
    GpuMesh(GpuMesh&& other) noexcept;
    GpuMesh& operator=(GpuMesh&& other) noexcept;

    void bind() const; // makes this mesh's vertex array current
    void draw() const; // draws all triangles; call bind() first
    // Draws `count` instances; per-instance attributes must be set up on this vertex array.
    void draw_instanced(GLsizei count) const;
    GLsizei index_count() const { return index_count_; }
    // Bounds of the vertices in mesh space, for culling and sizing: the largest |x|, |y|, |z|
    // and the largest distance from the origin.
    glm::vec3 half_extent() const { return half_extent_; }
    float radius() const { return radius_; }

  private:
    void destroy();

    GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
    GLsizei index_count_ = 0;
    glm::vec3 half_extent_{0.0f};
    float radius_ = 0.0f;
};

} // namespace tumble::render
