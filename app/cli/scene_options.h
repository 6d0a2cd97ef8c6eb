#pragma once
// Options shared by every command that runs a scene, and loading the scene they name with their
// overrides applied.
#include "app/run/run_request.h"
#include "app/scene/scene.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace tumble::app {

struct SceneOptions {
    std::string scene; // file or built-in name; empty: the built-in default
    RunRequest run;    // --integrator, --tolerance, --duration, --dt, --[no-]error-estimate
    int threads = 1;   // physics threads for the contact stage (same states for any count)
    bool quiet = false;
};

// Registers the scene argument, --integrator, --tolerance, --contact-tolerance, --duration, --dt, --threads and --quiet.
void add_scene_options(CLI::App* cmd, SceneOptions& o);

// Registers --error-estimate[=T1,T2,...] and --no-error-estimate (render, simulate, explain).
void add_error_estimate_options(CLI::App* cmd, SceneOptions& o);

// Loads the scene, prints its warnings, and applies the overrides (apply_request(),
// app/run/run_request.h). Throws SceneError, naming the option or the JSON path of an estimate
// time outside the run.
Scene load_for_command(const SceneOptions& opts);

} // namespace tumble::app
