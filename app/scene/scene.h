#pragma once
// A scene as loaded from a file: the physics description (world + bodies), and how to draw it.
// The format is documented field by field in docs/scene-format.md.
#include "app/scene/camera_rig.h"
#include "app/scene/quantity.h"
#include "physics/accuracy_plan.h"
#include "physics/build.h"
#include "render/scene_view.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tumble::app {

struct BodyLook {
    std::string name;                         // from the scene, or "body <i>"
    glm::vec3 color{0.8f, 0.8f, 0.8f};        // sRGB
    float plane_extent = 20.0f;               // drawn side length of a plane, m
    std::uint32_t mesh_id = 0;                // mesh bodies: index into Scene::meshes
    std::optional<render::Material> material; // the scene's; else app/scene/materials.h's default
};

struct RenderSettings {
    // The largest frame Tumble draws, 8K UHD (checked in scene files, goldens and on the command
    // line before anything is allocated): one RGB frame is then 100 MB, and the pipeline holds a
    // few frames, the multisampled framebuffer and the encoder's lookahead besides.
    static constexpr int kMinSide = 16, kMaxWidth = 7680, kMaxHeight = 4320;
    int width = 1280;
    int height = 720;
    int fps = 60;
    CameraRig camera; // fixed, orbiting, following a body or on a path (app/scene/camera_rig.h)
    render::Light light;
    glm::vec3 background{0.62f, 0.72f, 0.85f};
    bool shadows = true;           // shadow map from the key light
    bool soft_shadows = true;      // shadow edges that harden towards the contact (light.angle)
    bool ambient_occlusion = true; // bodies darken the ground and each other where they meet
    bool reflections = false;      // the bodies mirrored in the ground
    bool antialiasing = true;      // 4x multisampling
    bool overlay = false; // time, step, integrator, energy, momentum in the top-left corner
    bool axes = false;    // every body's own x, y, z axes as red, green, blue rods
    bool vectors = false; // w and L arrows at each dynamic body (app/view/vector_arrows.h)

    // Teaching overlays (docs/scene-format.md): strip charts, trails, Poinsot's construction,
    // and the overlay text of one body. A body is named as written (with the JSON path or
    // option that named it, for errors) and resolved to its index once the bodies are known.
    struct BodyRef {
        std::string name, place;
        int index = -1; // -1: none (the scene's sums, for charts and the overlay)
    };
    std::vector<Quantity> chart; // one panel each; empty: no chart
    BodyRef chart_body, poinsot, overlay_body;
    double chart_window = 0.0; // s of time shown; 0: the whole run
    bool trails = false;
    double trail_seconds = 3.0;
    int trail_axis = -1; // 0, 1, 2: also trace the tip of this body axis
};

// Accuracy as a setting (docs/accuracy.md): world.integrator "auto" picks the cheapest integrator
// and step that meet world.tolerance (app/run/accuracy_choice.h); a tolerance with a named
// integrator is checked, not chosen for.
struct Accuracy {
    bool auto_integrator = false;
    std::optional<physics::Tolerance> tolerance;
    std::string
        tolerance_place; // where it was set ("/world/tolerance", "--tolerance"), for messages
    // Set once "auto" is resolved (app/run/accuracy_choice.h): the plan, and the wall time of its
    // pilot runs.
    std::optional<physics::AccuracyPlan> plan;
    double pilot_seconds = 0.0;
};

// world.error_estimate / --error-estimate: estimate each dynamic body's global error by step
// doubling (physics/error_estimate.h) and report it at the end and at `times`.
struct ErrorEstimateSettings {
    bool on = false;
    // On only because a tolerance is checked (world.tolerance, --tolerance), not asked for by
    // world.error_estimate or --error-estimate: a run that cannot carry the estimate (continued
    // from a checkpoint) goes on without the check, and says so.
    bool only_for_tolerance = false;
    std::vector<double> times; // s, besides the end; each reported at the nearest step
    std::string place; // where the times were given, for errors ("/world/error_estimate/times")
};

struct Scene {
    std::string source; // file path, or "builtin:<name>" for an embedded scene
    // ContentHash (app/scene/content_hash.h) of the scene's text and of each mesh file it read,
    // in reading order: what checkpoints and video shards record to tell whether they were made
    // from this scene. Command-line overrides are not in it (they are recorded apart).
    std::uint64_t content_hash = 0;
    std::string title;
    physics::WorldDef world;
    Accuracy accuracy;
    double duration = 10.0; // s of simulated (and rendered) time
    std::vector<physics::BodyDef> bodies;
    std::vector<BodyLook> looks; // one per body
    // The drawn triangles of the scene's mesh files, shared by every body using one (BodyLook::
    // mesh_id) and by every frame's SceneView (render uploads each once).
    std::vector<std::shared_ptr<const render::MeshData>> meshes;
    // Things worth telling the user that do not stop the run (e.g. bodies starting deeply
    // interpenetrated); commands print them to stderr as "tumble: warning: ...".
    std::vector<std::string> warnings;
    ErrorEstimateSettings error_estimate;
    RenderSettings render;
};

// Resolves the bodies that scene.render names (render.chart.body, render.poinsot,
// render.overlay_body, or the options that set them) against the scene's bodies (SceneError
// naming the file and the place when one is unknown), and checks what each needs: w and w_body
// charts and Poinsot's construction need a body that moves.
void resolve_render_bodies(Scene& scene);

// Loads a scene from JSON text; `source` names it in error messages. Throws SceneError.
Scene load_scene(const std::string& text, const std::string& source);

// Resolves a scene argument: an existing file path, or the name of a built-in scene ("default",
// "default.json", "lessons/intermediate_axis"). An empty argument means the built-in default
// scene. Throws SceneError.
Scene load_scene_argument(const std::string& argument);

// The scene's short name: "default" for the built-in "builtin:default.json", "flip" for the file
// "shots/flip.json"; "tumble" for a scene without a source. Default output names start with it.
std::string scene_name(const Scene& scene);

// Names of the built-in scenes (without .json): assets/scenes/ first, then its folders' scenes
// named with the folder ("lessons/intermediate_axis").
std::vector<std::string> builtin_scene_names();

} // namespace tumble::app
