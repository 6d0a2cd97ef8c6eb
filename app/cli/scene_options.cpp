#include "app/cli/scene_options.h"

#include <cstdio>
#include <string>

namespace tumble::app {

void add_scene_options(CLI::App* cmd, SceneOptions& o) {
    cmd->add_option("scene", o.scene,
                    "scene file, or a built-in scene name (default: the built-in default)");
    cmd->add_option("--integrator", o.run.integrator,
                    "override the scene's integrator (a name, or auto: see --tolerance)");
    cmd->add_option("--tolerance", o.run.tolerance,
                    "R[,P]: the largest error of each body over the run, rad (and m; default R): "
                    "picks the cheapest integrator and step that meet it, or checks the one "
                    "--integrator names (docs/accuracy.md)");
    cmd->add_option("--contact-tolerance", o.run.contact_tolerance,
                    "M: the largest sag of a loaded contact the contact solver's effort on demand "
                    "accepts, m (world.contact_tolerance; docs/contacts.md)");
    cmd->add_option("--duration", o.run.duration, "override the scene's duration, s");
    cmd->add_option("--dt", o.run.dt, "override the scene's time step, s");
    cmd->add_option("--threads", o.threads,
                    "physics threads for contacts (default 1; the states are identical for any "
                    "count)")
        ->check(CLI::Range(1, 64));
    cmd->add_flag("-q,--quiet", o.quiet, "no progress bar and no summary");
}

void add_error_estimate_options(CLI::App* cmd, SceneOptions& o) {
    cmd->add_flag(std::string("--error-estimate{") + kEstimateOn + "}", o.run.error_estimate,
                  "estimate each moving body's error (rad, m) by step doubling and report it in "
                  "the summary, the diagnostics CSV and the overlay; =T1,T2,... also at these "
                  "times, s (about 3x the stepping cost; docs/error-estimate.md)");
    cmd->add_flag("--no-error-estimate", o.run.no_error_estimate,
                  "no error estimate, even if the scene asks for one");
}

Scene load_for_command(const SceneOptions& opts) {
    Scene scene = load_scene_argument(opts.scene);
    for (const std::string& w : scene.warnings)
        std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());
    apply_request(scene, opts.run);
    return scene;
}

} // namespace tumble::app
