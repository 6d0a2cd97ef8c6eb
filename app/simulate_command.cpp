// `tumble simulate`: step a scene without rendering and write the trajectory and diagnostics as
// CSV. Uses the same time step as `tumble render` (see timeline.h), so row t = k / fps holds the
// state that frame k shows.
#include "app/commands.h"
#include "app/interrupt.h"
#include "app/progress.h"
#include "app/scene_error.h"
#include "app/scene_options.h"
#include "app/simulation.h"
#include "app/timeline.h"
#include "app/trajectory_writer.h"
#include "physics/step.h"

#include <cstdio>

namespace tumble::app {

int run_simulate(const SimulateCommand& cmd) {
    Scene scene;
    Timeline tl;
    Simulation sim;
    try {
        scene = load_for_command(cmd.common);
        tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
        sim = make_simulation(scene, tl.h, cmd.common.threads);
    } catch (const SceneError& e) {
        return report_error(e.what(), kBadInput);
    }
    if (const std::string note = threads_note(sim, cmd.common.threads);
        !note.empty() && !cmd.common.quiet)
        std::fprintf(stderr, "tumble: note: %s\n", note.c_str());
    try {
        TrajectoryWriter out(cmd.output, scene);
        InterruptGuard guard;
        const std::int64_t total = tl.total_steps();
        Progress progress("simulating", total, cmd.common.quiet);
        out.write(sim.model, sim.state);
        bool interrupted = false;
        for (std::int64_t k = 1; k <= total; ++k) {
            if (InterruptGuard::requested()) {
                interrupted = true;
                break;
            }
            sim.step();
            if (k % cmd.every == 0 || k == total) out.write(sim.model, sim.state);
            progress.update(k);
        }
        progress.finish();
        out.finish();
        if (!cmd.common.quiet)
            std::fprintf(stderr, "tumble: %s: %lld steps of %.9g s; wrote %s and %s\n",
                         scene.source.c_str(), static_cast<long long>(sim.state.step), tl.h,
                         out.states_path().c_str(), out.diagnostics_path().c_str());
        return interrupted ? 128 + InterruptGuard::signal_number() : kOk;
    } catch (const physics::DivergenceError& e) {
        return report_error(scene.source + ": " + e.what(), kRunFailed);
    } catch (const std::exception& e) {
        return report_error(e.what(), kRunFailed);
    }
}

} // namespace tumble::app
