#pragma once
// What a run is asked beyond its scene file: the overrides of the command line (--integrator,
// --tolerance, --duration, --dt, --error-estimate) and of the Python module's keyword arguments,
// with one meaning and one set of error messages for both (they name the option, as the CLI
// spells it, and what was expected).
#include "app/scene/scene.h"

#include <optional>
#include <string>

namespace tumble::app {

inline constexpr const char* kEstimateOn = "on";

struct RunRequest {
    std::optional<std::string> integrator; // a registry name, or "auto"
    std::optional<std::string> tolerance;  // "R" or "R,P" (rad, m)
    std::optional<double> duration;        // s
    std::optional<double> dt;              // s
    std::optional<double> contact_tolerance; // m: world.contact_tolerance
    // kEstimateOn, or "T1,T2,...": times in s; unset: the scene's world.error_estimate.
    std::optional<std::string> error_estimate;
    bool no_error_estimate = false;
};

// Applies the request to the scene. Throws SceneError naming the option (or the JSON path of an
// estimate time outside the run) and io::BadInput for options that contradict each other.
void apply_request(Scene& scene, const RunRequest& request);

} // namespace tumble::app
