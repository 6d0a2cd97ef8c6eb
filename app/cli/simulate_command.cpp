// `tumble simulate`: step a scene without rendering and write the trajectory and diagnostics as
// CSV. Uses the same time step as `tumble render` (see app/run/timeline.h), so row t = k / fps
// holds the state that frame k shows. `-o -` streams the states to standard output.
#include "app/cli/failure.h"
#include "app/cli/scene_options.h"
#include "app/cli/stale_temporaries.h"
#include "app/cli/subcommand.h"
#include "app/run/interrupt.h"
#include "app/run/peak_memory.h"
#include "app/run/progress.h"
#include "app/run/run_estimate.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/run/trajectory_writer.h"
#include "io/bad_input.h"

#include <cstdio>
#include <memory>
#include <optional>

namespace tumble::app {
namespace {

struct SimulateCommand {
    SceneOptions common;
    std::string output;                     // states CSV, or "-" for standard output
    std::optional<std::string> diagnostics; // default <stem>.diagnostics.csv; "" for none
    int every = 1;                          // write every N-th step
};

// Diagnostics go beside the states, unless the states go to standard output (then only where
// --diagnostics says: two tables cannot share one stream).
std::string diagnostics_output(const SimulateCommand& cmd) {
    if (cmd.diagnostics && *cmd.diagnostics == cmd.output)
        throw io::BadInput("--diagnostics " + cmd.output +
                           ": the states already go there; two tables cannot share one output");
    if (cmd.diagnostics) return *cmd.diagnostics == "none" ? "" : *cmd.diagnostics;
    if (cmd.output == "-") {
        if (!cmd.common.quiet)
            std::fprintf(stderr, "tumble: note: states go to standard output; diagnostics are "
                                 "written only with --diagnostics FILE\n");
        return "";
    }
    return diagnostics_path_for(cmd.output);
}

void report(const SimulateCommand& cmd, const Scene& scene, const Simulation& sim, double h,
            const std::vector<std::string>& written, bool interrupted) {
    if (cmd.common.quiet) return;
    std::string files;
    for (const std::string& w : written) files += (files.empty() ? "" : " and ") + w;
    std::fprintf(stderr, "tumble: %s: %s%lld steps of %.9g s, %s; wrote %s\n", scene.source.c_str(),
                 interrupted ? "interrupted after " : "", static_cast<long long>(sim.state.step), h,
                 describe_peak_memory().c_str(), files.c_str());
    for (const std::string& line : estimate_summary(sim))
        std::fprintf(stderr, "tumble: %s\n", line.c_str());
    if (interrupted && cmd.output != "-")
        std::fprintf(stderr,
                     "tumble: a trajectory cut short is kept apart: '%s' is as it was before\n",
                     cmd.output.c_str());
}

int run_simulate(const SimulateCommand& cmd) {
    const Scene scene = load_for_command(cmd.common);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    Simulation sim = make_simulation(scene, tl.h, cmd.common.threads);
    start_error_estimate(sim, scene, cmd.common.threads);
    for (const std::string& note : {tl.adjustment_note(), threads_note(sim, cmd.common.threads)})
        if (!note.empty() && !cmd.common.quiet)
            std::fprintf(stderr, "tumble: note: %s\n", note.c_str());
    const std::string diagnostics = diagnostics_output(cmd);
    for (const std::string& path : {cmd.output, diagnostics})
        remove_stale_temporaries_for(path, cmd.common.quiet);
    InterruptGuard guard; // from before the files exist: no signal can leave them half-written
    TrajectoryWriter out(cmd.output, diagnostics, scene, sim.estimate.estimator.get());
    const std::int64_t total = tl.end_step(); // the last row at t = duration
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
    const std::vector<std::string> written = interrupted ? out.finish_interrupted() : out.finish();
    report(cmd, scene, sim, tl.h, written, interrupted);
    return interrupted ? interrupted_exit_code(InterruptGuard::signal_number()) : kOk;
}

} // namespace

Subcommand add_simulate_command(CLI::App& app) {
    auto cmd = std::make_shared<SimulateCommand>();
    CLI::App* s = app.add_subcommand(
        "simulate", "step a scene without rendering; write states and diagnostics as CSV");
    add_scene_options(s, cmd->common);
    add_error_estimate_options(s, cmd->common);
    s->add_option("-o,--output", cmd->output,
                  "states CSV, or - for standard output (diagnostics go to "
                  "<stem>.diagnostics.csv); a run cut short by Ctrl-C goes to "
                  "<stem>.interrupted.csv")
        ->required();
    s->add_option("--diagnostics", cmd->diagnostics,
                  "diagnostics CSV (default <stem>.diagnostics.csv; none: do not write them)");
    s->add_option("--every", cmd->every, "write every N-th step (default 1)")
        ->check(CLI::PositiveNumber);
    return {[s] { return s->parsed(); }, [cmd] { return run_simulate(*cmd); }};
}

} // namespace tumble::app
