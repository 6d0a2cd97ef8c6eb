#pragma once
// Instanced drawing. A frame's instances are grouped into batches, one per (mesh, face culling)
// pair, and each batch is one glDrawElementsInstanced call whose per-instance data (transform,
// colour, material) comes from one shared vertex buffer. On llvmpipe a draw call with its
// uniform updates costs about as much as a few thousand triangles, so 1000 spheres as 1000 draws
// spend more time in the driver than in the rasteriser; as a handful of batches they do not.
//
// Also here, as plain functions that tests can check without GL: view-frustum culling and the
// level of detail (how many segments a sphere or cylinder needs at its size on screen).
#include "render/mesh.h"
#include "render/scene_view.h"

#include <GL/gl.h>
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tumble::render {

// One instance as the shaders read it: vertex attributes 2..13 with divisor 1 (lit.vert).
struct InstanceData {
    glm::mat4 model;    // unit mesh -> world (locations 2-5)
    glm::vec4 color;    // linear base colour; a = 1 on the checkered ground (location 6)
    glm::vec4 material; // Blinn-Phong shininess, specular, metallic, gloss (location 7)
    // The two occluders that darken this instance's sky most, three rows each
    // (ambient_occlusion.h); no_occluder() where there are fewer (locations 8-13).
    std::array<glm::vec4, 6> occluders;
};

// The shader inputs of an instance, `color` given in sRGB, with no occluders.
InstanceData make_instance_data(const glm::mat4& model, glm::vec3 color, const Material& material,
                                bool checker);

// Material::roughness in [0, 1] -> Blinn-Phong exponent: 1025 (polished) down to 2 (matte),
// evenly spaced in log2 so that equal steps of roughness look like equal steps.
float shininess_from_roughness(float roughness);

struct Batch {
    const GpuMesh* mesh = nullptr;
    bool cull_back = true;   // closed meshes hide their back faces; planes and OBJ meshes do not
    std::uint32_t first = 0; // index of the first instance in BatchList::data()
    std::uint32_t count = 0;
    int rank = 0; // BatchList::add's: the ground's batches have kGroundRank
};

// The rank of ground planes' batches (draw_list.cpp): drawn last, and on their own when the
// renderer blends a floor reflection under them.
constexpr int kGroundRank = 1;

// Instances grouped by (mesh, culling), in the order of `rank` (lower first), then of first use;
// within a group, nearest first by `distance` (front to back: the depth test then rejects the
// hidden parts of later instances before they are shaded, which on llvmpipe is most of the cost
// of a crowd). clear() keeps every buffer's capacity: a warmed-up list allocates nothing.
class BatchList {
  public:
    void clear();
    void add(const GpuMesh* mesh, bool cull_back, int rank, const InstanceData& instance,
             float distance = 0.0f);
    void finish(); // lays the groups out contiguously in data() and lists them in batches()

    const std::vector<Batch>& batches() const { return batches_; }
    const std::vector<InstanceData>& data() const { return data_; }
    std::uint64_t triangles() const; // total over all instances (after finish())

  private:
    struct Group {
        const GpuMesh* mesh;
        bool cull_back;
        int rank;
        std::vector<InstanceData> items;
        std::vector<float> distances;
        std::vector<std::uint32_t> order;
    };
    std::vector<Group> groups_; // groups_[0, used_) are this frame's; the rest are spare
    std::size_t used_ = 0;
    std::vector<std::size_t> order_;
    std::vector<Batch> batches_;
    std::vector<InstanceData> data_;
};

// The GL side: a vertex buffer holding a BatchList's instances, and the draw calls.
class InstanceBuffer {
  public:
    InstanceBuffer(); // needs a current GL context
    ~InstanceBuffer();
    InstanceBuffer(const InstanceBuffer&) = delete;
    InstanceBuffer& operator=(const InstanceBuffer&) = delete;

    void upload(const BatchList& list);
    // Draws the batches of the uploaded list, every one or only those whose rank is (or, with
    // `except`, is not) `rank`. Batches with cull_back cull the face named by `cull_face`
    // (GL_BACK for the camera, GL_FRONT for the shadow map), the others cull none.
    enum class Select { All, Rank, ExceptRank };
    void draw(const BatchList& list, GLenum cull_face, Select select = Select::All,
              int rank = 0) const;

  private:
    GLuint vbo_ = 0;
    std::size_t capacity_ = 0; // bytes
};

// The six planes of a view frustum (Gribb and Hartmann, "Fast extraction of viewing frustum
// planes from the world-view-projection matrix", 2001), each (n, d) with unit n pointing inwards:
// a point x is inside when dot(n, x) + d >= 0 for all six.
struct Frustum {
    std::array<glm::vec4, 6> planes;

    static Frustum from_view_proj(const glm::mat4& view_proj);
    bool intersects_sphere(glm::vec3 centre, float radius) const;
    // Whether the sphere swept from `centre` along `direction` to infinity can reach inside: the
    // region an object can throw a shadow into, for a light travelling along `direction`.
    // Conservative (plane by plane): may say yes for a sweep that passes a corner.
    bool intersects_swept_sphere(glm::vec3 centre, float radius, glm::vec3 direction) const;
    // The same frustum with its far plane `distance` in front of `eye` (the camera's position),
    // for a perspective camera: the part of the view within that distance.
    Frustum cut_at(glm::vec3 eye, float distance) const;
};

// Segments around a circle of `radius_px` pixels so that the polygon departs from the circle by
// at most `max_error_px`, r (1 - cos(pi / N)) <= e, and no edge is longer than `max_edge_px`:
// the eye picks out long straight edges on a big round outline even when they stay within a
// fraction of a pixel of it.
int segments_for(float radius_px, float max_error_px, float max_edge_px = 1e9f);

// The first of `levels` (ascending segment counts) with at least segments_for(...); the last
// level when none has enough.
std::size_t choose_level(std::span<const int> levels, float radius_px, float max_error_px,
                         float max_edge_px = 1e9f);

// Radius on screen, in pixels, of a sphere of `radius` at `distance` from a perspective camera
// with vertical field of view `fov_y_deg` drawing `height_px` rows.
float projected_radius_px(float radius, float distance, float fov_y_deg, int height_px);

} // namespace tumble::render
