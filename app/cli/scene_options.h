#pragma once
// Options shared by every command that runs a scene, and loading the scene they name with their
// overrides applied.
#include "app/scene/scene.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace tumble::app {

struct SceneOptions {
    std::string scene; // file or built-in name; empty: the built-in default
    std::optional<std::string> integrator; // a registry name, or "auto"
    std::optional<std::string> tolerance;  // "R" or "R,P" (rad, m)
    std::optional<double> duration;
    std::optional<double> dt;
    int threads = 1; // physics threads for the contact stage (same states for any count)
    bool quiet = false;
    // --error-estimate[=T1,T2,...] (kEstimateOn without times) and --no-error-estimate; unset:
    // the scene's world.error_estimate.
    std::optional<std::string> error_estimate;
    bool no_error_estimate = false;
};

inline constexpr const char* kEstimateOn = "on";

// Registers the scene argument, --integrator, --tolerance, --duration, --dt, --threads and --quiet.
void add_scene_options(CLI::App* cmd, SceneOptions& o);

// Registers --error-estimate[=T1,T2,...] and --no-error-estimate (render, simulate, explain).
void add_error_estimate_options(CLI::App* cmd, SceneOptions& o);

// Loads the scene, prints its warnings, and applies the overrides (integrator, tolerance, duration,
// dt, the error estimate). Throws SceneError, naming the option or the JSON path of an estimate
// time outside the run.
Scene load_for_command(const SceneOptions& opts);

} // namespace tumble::app
