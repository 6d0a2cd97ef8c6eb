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
};

// Registers the scene argument, --integrator, --tolerance, --duration, --dt, --threads and --quiet.
void add_scene_options(CLI::App* cmd, SceneOptions& o);

// Loads the scene, prints its warnings, and applies the overrides (integrator, tolerance, duration,
// dt).
// Throws SceneError.
Scene load_for_command(const SceneOptions& opts);

} // namespace tumble::app
