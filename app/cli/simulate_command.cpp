// `tumble simulate`: step a scene without rendering and write the trajectory and diagnostics as
// CSV. Uses the same time step as `tumble render` (see app/run/timeline.h), so row t = k / fps
// holds the state that frame k shows.
#include "app/cli/failure.h"
#include "app/cli/scene_options.h"
#include "app/cli/subcommand.h"
#include "app/run/interrupt.h"
#include "app/run/progress.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/run/trajectory_writer.h"

#include <cstdio>
#include <memory>

namespace tumble::app {
namespace {

struct SimulateCommand {
    SceneOptions common;
    std::string output; // states CSV; diagnostics go beside it as <stem>.diagnostics.csv
    int every = 1;      // write every N-th step
};

int run_simulate(const SimulateCommand& cmd) {
    const Scene scene = load_for_command(cmd.common);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    Simulation sim = make_simulation(scene, tl.h, cmd.common.threads);
    for (const std::string& note : {tl.adjustment_note(), threads_note(sim, cmd.common.threads)})
        if (!note.empty() && !cmd.common.quiet)
            std::fprintf(stderr, "tumble: note: %s\n", note.c_str());
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
    return interrupted ? interrupted_exit_code(InterruptGuard::signal_number()) : kOk;
}

} // namespace

Subcommand add_simulate_command(CLI::App& app) {
    auto cmd = std::make_shared<SimulateCommand>();
    CLI::App* s = app.add_subcommand(
        "simulate", "step a scene without rendering; write states and diagnostics as CSV");
    add_scene_options(s, cmd->common);
    s->add_option("-o,--output", cmd->output,
                  "states CSV (diagnostics go to <stem>.diagnostics.csv)")
        ->required();
    s->add_option("--every", cmd->every, "write every N-th step (default 1)")
        ->check(CLI::PositiveNumber);
    return {[s] { return s->parsed(); }, [cmd] { return run_simulate(*cmd); }};
}

} // namespace tumble::app
