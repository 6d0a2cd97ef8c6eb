// Fuzz target: the OBJ text of a mesh body, read exactly as the scene loader reads it
// (app/scene/shape_loader.cpp): check_obj_lines, parse_obj, check_closed_mesh, the drawn mesh,
// the mass from the mesh's volume, then the model build (hull, inertia) and the initial-overlap
// check against a floor and a ball. The input is written as m.obj beside a fixed scene naming it
// (a per-process scratch folder) and the scene is loaded. Asserts: a scene whose mesh body has at
// least 4 triangles and a positive finite mass, or io::BadInput (SceneError) with a short message
// naming the scene; any other exception, a crash, a hang or a sanitizer report is a finding.
#include "app/scene/scene.h"
#include "harness_support.h"
#include "io/bad_input.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace {

// Body 1 is the mesh, sitting on the floor with a ball at its origin.
constexpr const char* kScene = R"({"format_version": 1, "world": {"duration": 0.1},
  "bodies": [{"shape": {"type": "plane"}},
             {"shape": {"type": "mesh", "file": "m.obj"}},
             {"shape": {"type": "sphere", "radius": 0.05}}]})";

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using tumble::fuzz::require;
    tumble::fuzz::write_scratch("m.obj", data, size);
    const std::string source = (tumble::fuzz::scratch_dir() / "scene.json").string();
    try {
        const tumble::app::Scene scene = tumble::app::load_scene(kScene, source);
        require(scene.bodies.size() == 3 && scene.bodies[1].mesh, "the mesh body loaded");
        require(scene.bodies[1].mesh->triangles.size() >= 4, "a closed mesh has 4+ triangles");
        const double mass = scene.bodies[1].mass;
        require(std::isfinite(mass) && mass > 0.0, "the mesh body's mass is positive and finite");
        tumble::fuzz::last_verdict() = tumble::fuzz::Verdict::kLoaded;
    } catch (const tumble::io::BadInput& e) {
        tumble::fuzz::last_verdict() = tumble::fuzz::Verdict::kRefused;
        tumble::fuzz::require_clear_error(e.what(), source);
    }
    return 0;
}
