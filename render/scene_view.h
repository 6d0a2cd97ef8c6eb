#pragma once
// What the renderer draws in one frame: a camera, a light and a flat list of shape instances.
// The renderer knows nothing of physics or integrators; the app fills this from the state.
#include "render/mesh_data.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace tumble::render {

struct Camera {
    glm::vec3 position{4.0f, -6.0f, 3.0f};
    glm::vec3 target{0.0f, 0.0f, 1.0f};
    glm::vec3 up{0.0f, 0.0f, 1.0f}; // Tumble's world is z-up
    float fov_y_deg = 45.0f;        // vertical field of view, degrees
    float z_near = 0.05f;
    float z_far = 200.0f;
};

struct Light {
    glm::vec3 direction{-0.4f, 0.3f,
                        -1.0f};        // direction the light travels (world), need not be unit
    glm::vec3 color{1.0f, 1.0f, 1.0f}; // linear RGB intensity of the key light
    float ambient = 0.25f;             // ambient term, fraction of the base colour
};

enum class MeshKind : std::uint8_t { Sphere, Box, Plane, Cylinder, Custom };

// Index into SceneView::meshes, for instances of MeshKind::Custom.
using MeshId = std::uint32_t;

// One drawn shape. `transform` maps the unit mesh to the world: the unit sphere has radius 1,
// the unit box spans [-1,1]^3 (so scale by half extents), the plane is z = 0 with normal +z and
// is drawn as a large square (scale x,y to choose its extent), the unit cylinder has radius 1
// around the z axis and spans z in [-1,1] with both ends capped (scale z by the half length). A
// Custom instance draws SceneView::meshes[mesh_id] as given (its vertices are in body frame:
// transform is then just the body's pose); custom meshes are drawn two-sided, so a mesh wound
// the wrong way round still shows its outside.
struct Instance {
    MeshKind mesh = MeshKind::Sphere;
    glm::mat4 transform{1.0f};
    glm::vec3 color{0.8f, 0.8f, 0.8f}; // sRGB base colour in [0,1]
    MeshId mesh_id = 0;                // MeshKind::Custom only
};

struct SceneView {
    Camera camera;
    Light light;
    glm::vec3 background{0.62f, 0.72f, 0.85f}; // sRGB
    std::vector<Instance> instances;
    // Triangle meshes for MeshKind::Custom instances, indexed by Instance::mesh_id. The renderer
    // uploads each mesh the first time it sees it and keeps the GPU copy while the MeshData is
    // alive (it holds a weak_ptr), so pass the same shared_ptr every frame: copying it into the
    // view costs a reference count, not an upload. A MeshData must not change once shared.
    std::vector<std::shared_ptr<const MeshData>> meshes;
};

} // namespace tumble::render
