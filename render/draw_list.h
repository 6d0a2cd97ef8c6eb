#pragma once
// From a SceneView to the batches of one frame (batches.h): which meshes to draw, at which level
// of detail, with which per-instance data, for the camera and for the shadow map.
//   - Culling: instances whose bounding sphere is outside the camera's frustum are skipped;
//     shadow casters are kept when their shadow can fall inside it.
//   - Level of detail: spheres and cylinders use the fewest segments that keep their outline
//     within kCameraError pixels of the true circle on screen (kShadowError texels in the shadow
//     map). A 64-segment sphere is 4032 triangles; one 20 pixels across needs 24 segments (528).
//   - Order: nearest first within each batch (BatchList), the ground last.
//   - Body axes: an instance with `axes` adds three thin cylinders (x red, y green, z blue).
//   - Ambient occlusion: each body's two nearest occluders go into its instance data, and each
//     body near a plane gets a ground decal (ambient_occlusion.h).
#include "render/ambient_occlusion.h"
#include "render/batches.h"
#include "render/mesh.h"
#include "render/scene_view.h"
#include "render/shadow_map.h"

#include <array>
#include <vector>

namespace tumble::render {

// The built-in unit meshes, at several levels of detail. Needs a current GL context.
struct MeshLibrary {
    static constexpr std::array<int, 7> kSphereLevels{8, 12, 16, 24, 32, 48, 64};
    static constexpr std::array<int, 3> kCylinderLevels{12, 24, 48};
    std::vector<GpuMesh> spheres;   // one per kSphereLevels entry
    std::vector<GpuMesh> cylinders; // one per kCylinderLevels entry
    GpuMesh box, plane;

    MeshLibrary();
};

struct DrawSettings {
    glm::mat4 view_proj{1.0f}; // the camera's
    int height = 720;          // image rows, for sizes on screen
    bool shadows = true;
    int shadow_map_size = 1024;    // at most
    float shadow_distance = 50.0f; // casters farther from the camera than this cast no shadow
    bool ambient_occlusion = true;
};

// A shadow caster waiting for the light's frustum, which depends on all of them.
struct PendingCaster {
    InstanceData data;
    const GpuMesh* custom; // MeshKind::Custom only
    float lod_radius;      // metres; 0 for meshes without levels of detail
    MeshKind kind;
    bool closed;
};

struct DrawLists {
    BatchList camera; // what the camera sees
    BatchList shadow; // shadow casters, at the shadow map's level of detail
    LightFrame light; // empty when shadows are off or nothing casts one
    // Scratch, kept between frames so that building allocates nothing once warmed up.
    std::vector<glm::vec4> caster_bounds; // xyz centre, w radius
    std::vector<PendingCaster> casters;
    // Ambient occlusion: the ground decals the camera sees, and the scratch that finds them.
    std::vector<Decal> decals;
    std::vector<Occluder> occluders;
    std::vector<Receiver> receivers;
    std::vector<std::int32_t> receiver_of; // per view instance: index into receivers, or -1
    std::vector<std::array<std::int32_t, 2>> nearest;
    std::vector<std::int32_t> occluder_order;
};

// Half a pixel of outline error is below what the eye picks out, with or without MSAA (compared
// side by side on the 1000-sphere benchmark: 12 instead of 16 segments for a sphere 15 pixels
// across, 120k instead of 224k triangles, 20 ms less per frame).
constexpr float kCameraError = 0.6f; // pixels
constexpr float kCameraEdge = 10.0f; // pixels: longest outline edge (big spheres looked faceted)
constexpr float kShadowError = 2.0f; // shadow-map texels (the shadow filter blurs over two)

// Rebuilds `out` for this frame. `custom[i]` is the GPU copy of view.meshes[i]. Throws
// RenderError when an instance names a custom mesh the view does not have.
void build_draw_lists(const SceneView& view, const DrawSettings& settings,
                      const MeshLibrary& library, const std::vector<const GpuMesh*>& custom,
                      DrawLists& out);

} // namespace tumble::render
