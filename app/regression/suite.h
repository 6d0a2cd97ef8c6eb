#pragma once
// A regression suite (docs/regression-testing.md): scenes, and for each, image checks (chosen
// frames drawn and compared with golden PNGs, anti-aliasing-aware, with masks) and state checks
// (named bodies' poses and velocities and the scene's energy and momenta at chosen frames,
// compared with a golden trajectory within absolute tolerances). Loaded and checked whole before
// anything runs: a bad suite names the file and the JSON path and exits 2.
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "render/image_compare.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tumble::app {

inline constexpr int kSuiteFormatVersion = 1;

// What a state check can compare (StateQuantity: errors between two states, not the catalogue of
// app/scene/quantity.h, which is what a run shows); each with an absolute tolerance in SI units or
// radians.
enum class StateQuantity {
    kPosition,        // body origin, m (distance between the two positions)
    kOrientation,     // rad (angle of the rotation between the two orientations)
    kVelocity,        // m/s (norm of the difference)
    kAngularVelocity, // rad/s
    kEnergy,          // J, the scene's total energy
    kMomentum,        // kg m/s, the scene's linear momentum (norm of the difference)
    kAngularMomentum, // kg m^2/s, about the world origin
};
const char* quantity_name(StateQuantity q); // "angular_velocity"
const char* quantity_unit(StateQuantity q); // "rad/s"
bool per_body(StateQuantity q);             // position .. angular_velocity

struct Mask { // pixels to ignore, from the image's top-left corner
    int x = 0, y = 0, width = 0, height = 0;
};

struct ImageCheck {
    std::string name;  // unique in the suite; also the golden's file name without ".png"
    std::string where; // JSON path of its entry in the suite, for messages
    std::int64_t frame = 0;
    int width = 320, height = 180;
    bool overlay = false;
    render::CompareOptions compare;
    std::vector<Mask> masks;
    std::filesystem::path golden; // <goldens>/<name>.png
};

struct Tolerance {
    StateQuantity quantity;
    double absolute = 0.0;
};

struct StateCheck {
    std::string name;
    std::string where;
    std::vector<std::string> bodies;   // as the scene names them
    std::vector<int> body_indices;     // the same, as indices into the scene's bodies
    std::vector<std::int64_t> frames;  // sampled frames, increasing
    std::vector<Tolerance> quantities; // in the order of StateQuantity
    std::filesystem::path golden;      // <goldens>/<name>.csv; diagnostics beside it
    std::filesystem::path golden_diagnostics() const;
};

struct SuiteScene {
    std::string name;     // prefix of its checks' names: the file's stem, or the entry's "name"
    std::string argument; // as the suite gives it
    Scene scene;
    Timeline timeline;
    std::vector<ImageCheck> images;
    std::vector<StateCheck> states;
};

struct Suite {
    std::filesystem::path path;    // as given on the command line
    std::filesystem::path goldens; // folder of the golden files
    std::string title;
    std::vector<SuiteScene> scenes;
    std::size_t check_count() const;
};

// Reads and checks a suite, loading every scene it names (scene paths are relative to the
// suite's folder; a bare name that is no file there is a built-in scene). Throws SceneError.
Suite load_suite(const std::filesystem::path& path);

} // namespace tumble::app
