// Fuzz target: the scene loader (app/scene/scene.h), JSON text in, a scene or a clear error out.
// Asserts, for any bytes: load_scene() returns a scene with one look per body (never for a text
// holding a NUL byte: JSON has none), or throws io::BadInput (SceneError) whose message names the
// scene first and stays short (no message quotes a whole value); any other exception, a crash, a
// hang or a sanitizer report is a finding. The source is "builtin:fuzz.json": mesh files are then
// looked up among the bundled meshes only (app/scene/obj_mesh.h), so no input reads the disk.
#include "app/scene/scene.h"
#include "harness_support.h"
#include "io/bad_input.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

constexpr const char* kSource = "builtin:fuzz.json";

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using tumble::fuzz::require;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const tumble::app::Scene scene = tumble::app::load_scene(text, kSource);
        require(scene.looks.size() == scene.bodies.size(), "one look per body");
        require(scene.source == kSource, "the scene keeps its source");
        require(text.find('\0') == std::string::npos, "a NUL byte is refused (JSON has none)");
        tumble::fuzz::last_verdict() = tumble::fuzz::Verdict::kLoaded;
    } catch (const tumble::io::BadInput& e) {
        tumble::fuzz::last_verdict() = tumble::fuzz::Verdict::kRefused;
        tumble::fuzz::require_clear_error(e.what(), kSource);
    }
    return 0;
}
