#pragma once
// Loading a scene for a command and applying the command-line overrides, with one error path.
#include "app/commands.h"
#include "app/scene.h"

namespace tumble::app {

// Loads the scene and applies overrides (integrator, duration, dt). Throws SceneError.
Scene load_for_command(const SceneOptions& opts);

// Prints "tumble: error: <what>" to stderr and returns `code`.
int report_error(const std::string& what, int code);

} // namespace tumble::app
