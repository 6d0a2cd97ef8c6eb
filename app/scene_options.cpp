#include "app/scene_options.h"

#include "app/scene_error.h"

#include <cstdio>

namespace tumble::app {

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

int report_error(const std::string& what, int code) {
    std::fprintf(stderr, "tumble: error: %s\n", what.c_str());
    return code;
}

} // namespace tumble::app
