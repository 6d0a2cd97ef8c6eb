#include "app/cli/scene_options.h"

#include "app/scene/scene_error.h"

#include <cstdio>

namespace tumble::app {

void add_scene_options(CLI::App* cmd, SceneOptions& o) {
    cmd->add_option("scene", o.scene,
                    "scene file, or a built-in scene name (default: the built-in default)");
    cmd->add_option("--integrator", o.integrator, "override the scene's integrator");
    cmd->add_option("--duration", o.duration, "override the scene's duration, s");
    cmd->add_option("--dt", o.dt, "override the scene's time step, s");
    cmd->add_option("--threads", o.threads,
                    "physics threads for contacts (default 1; the states are identical for any "
                    "count)")
        ->check(CLI::Range(1, 64));
    cmd->add_flag("-q,--quiet", o.quiet, "no progress bar and no summary");
}

Scene load_for_command(const SceneOptions& opts) {
    Scene scene = load_scene_argument(opts.scene);
    for (const std::string& w : scene.warnings)
        std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());
    if (opts.integrator) {
        const auto id = physics::integrator_from_name(*opts.integrator);
        if (!id)
            throw SceneError("--integrator", *opts.integrator,
                             "unknown integrator; valid integrators: " +
                                 physics::integrator_names());
        scene.world.integrator = *id;
    }
    if (opts.duration) {
        if (!(*opts.duration > 0.0))
            throw SceneError("--duration", std::to_string(*opts.duration),
                             "expected a positive number of seconds");
        scene.duration = *opts.duration;
    }
    if (opts.dt) {
        if (!(*opts.dt > 0.0))
            throw SceneError("--dt", std::to_string(*opts.dt),
                             "expected a positive time step in seconds");
        scene.world.dt = *opts.dt;
    }
    return scene;
}

} // namespace tumble::app
