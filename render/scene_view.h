#pragma once
// What the renderer draws in one frame: a camera, a light and a flat list of shape instances.
// The renderer knows nothing of physics or integrators; the app fills this from the state.
#include "render/mesh_data.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
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
    // Angular diameter of the light seen from the scene, degrees: how fast shadows soften with
    // the distance from caster to receiver (soft shadows only). The sun's is 0.53; a slightly
    // overcast sun or a big softbox is a few degrees.
    float angle_deg = 2.5f;
};

enum class MeshKind : std::uint8_t { Sphere, Box, Plane, Cylinder, Custom };

// How a surface reflects light besides its colour: a small set of knobs, each in [0, 1].
//   roughness  0 = a small sharp highlight (polished) .. 1 = a broad faint one (matte)
//   specular   strength of the highlight and of the sky's reflection at grazing angles
//   metallic   0 = dielectric (white highlights over coloured diffuse light), 1 = metal (no
//              diffuse light; highlights and reflections take the base colour)
struct Material {
    float roughness = 0.45f;
    float specular = 0.5f;
    float metallic = 0.0f;
};

// Index into SceneView::meshes, for instances of MeshKind::Custom.
using MeshId = std::uint32_t;

// One drawn shape. `transform` maps the unit mesh to the world: the unit sphere has radius 1,
// the unit box spans [-1,1]^3 (so scale by half extents), the plane is z = 0 with normal +z and
// is drawn as a large square (scale x,y to choose its extent), the unit cylinder has radius 1
// around the z axis and spans z in [-1,1] with both ends capped (scale z by the half length). A
// Custom instance draws SceneView::meshes[mesh_id] as given (its vertices are in body frame:
// transform is then just the body's pose); custom meshes are drawn two-sided, so a mesh wound
// the wrong way round still shows its outside.
// Planes are drawn with a checkerboard (0.5 m squares) and cast no shadow. `axes` adds the body's
// own x, y, z axes as red, green and blue rods poking out of the shape (their lengths follow the
// transform's scale along each axis).
struct Instance {
    MeshKind mesh = MeshKind::Sphere;
    glm::mat4 transform{1.0f};
    glm::vec3 color{0.8f, 0.8f, 0.8f}; // sRGB base colour in [0,1]
    MeshId mesh_id = 0;                // MeshKind::Custom only
    Material material{};
    bool axes = false;
    // The body this shape belongs to (a capsule is three shapes of one body), for ambient
    // occlusion: a body darkens the ground and other bodies, never itself. -1: not a body (an
    // arrow or a marker), which neither casts nor receives it.
    std::int32_t body = -1;
};

// Lines in the world (trails, curves of a construction): polylines drawn as ribbons that face
// the camera, `width_px` wide on screen whatever their distance, hidden behind bodies, each point
// with its own sRGB colour and opacity (a trail fades along its length). Flat arrays: strip s
// is points[first, first + count).
struct Polylines {
    struct Strip {
        std::uint32_t first = 0, count = 0;
        float width_px = 2.0f;
    };
    std::vector<glm::vec3> points;
    std::vector<glm::vec4> colors; // one per point
    std::vector<Strip> strips;
    void clear() { points.clear(), colors.clear(), strips.clear(); }
    // Starts a strip; append its points with add().
    void begin(float width_px) { strips.push_back({std::uint32_t(points.size()), 0, width_px}); }
    void add(glm::vec3 p, glm::vec4 rgba) {
        points.push_back(p);
        colors.push_back(rgba);
        ++strips.back().count;
    }
};

// A translucent surface (render/glass.h): a construction's energy ellipsoid or plane, seen
// through. `transform` places the unit mesh as for an Instance (Sphere, Box, Cylinder or Plane;
// not Custom). Closed meshes show their far side through their near side.
struct Glass {
    MeshKind mesh = MeshKind::Sphere;
    glm::mat4 transform{1.0f};
    glm::vec4 rgba{1.0f, 1.0f, 1.0f, 0.25f}; // sRGB colour, opacity where it faces the eye
};

// Flat drawing over the picture (charts), in pixels from the image's top-left corner, sRGB
// colours with opacity: filled rectangles, then polylines, then text labels, each in order.
struct Canvas {
    struct Rect {
        glm::vec2 min, max;
        glm::vec4 rgba;
    };
    struct Strip {
        std::uint32_t first = 0, count = 0; // into points
        glm::vec4 rgba;
        float width_px = 1.5f;
    };
    struct Label {
        glm::vec2 at; // the baseline's left end (align -1), middle (0) or right end (1)
        std::string text;
        glm::vec4 rgba;
        int align = -1;
    };
    std::vector<Rect> rects;
    std::vector<glm::vec2> points;
    std::vector<Strip> strips;
    std::vector<Label> labels;
    bool empty() const { return rects.empty() && strips.empty() && labels.empty(); }
    void clear() { rects.clear(), points.clear(), strips.clear(), labels.clear(); }
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
    // Text drawn over a translucent panel, one entry per line (ASCII; other bytes show as '?').
    // Empty: no overlay. The panel's top-left corner is `overlay_at` (pixels from the image's
    // top-left corner; app/view/overlay_layout.h chooses it), or the top-left corner's margin
    // when negative.
    std::vector<std::string> overlay;
    glm::vec2 overlay_at{-1.0f, -1.0f};
    Polylines lines;          // trails and constructions, in the world
    std::vector<Glass> glass; // translucent surfaces of constructions, in the world
    Canvas canvas;            // charts and legends, over the picture
};

} // namespace tumble::render
