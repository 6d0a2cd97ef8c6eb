// `tumble simulate`: step a scene without rendering and write the trajectory and diagnostics as
// CSV. Uses the same time step as `tumble render` (see app/run/timeline.h), so row t = k / fps
// holds the state that frame k shows. `-o -` streams the states to standard output.
// --checkpoint-every K writes the complete state every K frames (app/cluster/checkpoint_store.h),
// with or without the CSV, for shards of a render to continue from (docs/cluster.md).
#include "app/cli/failure.h"
#include "app/cli/scene_options.h"
#include "app/cli/subcommand.h"
#include "app/cluster/checkpoint_store.h"
#include "app/run/accuracy_choice.h"
#include "app/run/peak_memory.h"
#include "app/run/prepare_run.h"
#include "app/run/progress.h"
#include "app/run/run_estimate.h"
#include "app/run/stale_temporaries.h"
#include "app/run/trajectory_writer.h"
#include "io/atomic_file.h"
#include "io/bad_input.h"
#include "io/interrupt.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

namespace tumble::app {
namespace {

struct SimulateCommand {
    SceneOptions common;
    std::string output;                     // states CSV, or "-" for standard output
    std::optional<std::string> diagnostics; // default <stem>.diagnostics.csv; "" for none
    int every = 1;                          // write every N-th step
    std::optional<int> fps;                 // frames per second (frame k at t = k / fps)
    int checkpoint_every = 0;               // frames between checkpoints; 0: none
    std::string checkpoints;                // their folder; default "<scene>_checkpoints/"
};

// The checkpoints' folder, created now (a folder that cannot be made is bad input, exit 2,
// before any stepping). Empty without --checkpoint-every.
std::filesystem::path checkpoint_folder(const SimulateCommand& cmd, const Scene& scene) {
    if (cmd.checkpoint_every == 0) {
        if (!cmd.checkpoints.empty())
            throw io::BadInput(
                "--checkpoints " + cmd.checkpoints +
                ": says where checkpoints go, but --checkpoint-every K is not given");
        return {};
    }
    const std::filesystem::path dir =
        cmd.checkpoints.empty() ? scene_name(scene) + "_checkpoints" : cmd.checkpoints;
    try {
        io::ensure_writable_directory(dir);
    } catch (const io::FileError& e) {
        throw io::BadInput(std::string("--checkpoints: ") + e.what());
    }
    return dir;
}

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
    if (files.empty()) files = "nothing";
    std::fprintf(stderr, "tumble: %s: %s%lld steps of %.9g s, %s; wrote %s\n", scene.source.c_str(),
                 interrupted ? "interrupted after " : "", static_cast<long long>(sim.state.step), h,
                 describe_peak_memory().c_str(), files.c_str());
    for (const std::string& line : describe_choice(scene, true))
        std::fprintf(stderr, "tumble: %s\n", line.c_str());
    for (const std::string& line : estimate_summary(sim))
        std::fprintf(stderr, "tumble: %s\n", line.c_str());
    if (const std::string e = effort_summary(sim); !e.empty())
        std::fprintf(stderr, "tumble: %s\n", e.c_str());
    report_tolerance(scene, sim);
    if (interrupted && cmd.output != "-")
        std::fprintf(stderr,
                     "tumble: a trajectory cut short is kept apart: '%s' is as it was before\n",
                     cmd.output.c_str());
}

int run_simulate(const SimulateCommand& cmd) {
    if (cmd.output.empty() && cmd.checkpoint_every == 0)
        throw io::BadInput("simulate: expected -o FILE (the states CSV, - for standard output), "
                           "--checkpoint-every K (checkpoints only), or both");
    io::InterruptGuard guard; // from the start: the pilots stop, and no file is left half-written
    Scene loaded = load_for_command(cmd.common);
    if (cmd.fps) loaded.render.fps = *cmd.fps; // as `tumble render --fps`: the same frame times
    PreparedRun run = prepare_run(std::move(loaded), {cmd.common.threads});
    const Scene& scene = run.scene;
    const Timeline& tl = run.timeline;
    Simulation& sim = run.sim;
    for (const std::string& note : run.notes(cmd.common.threads))
        if (!cmd.common.quiet) std::fprintf(stderr, "tumble: note: %s\n", note.c_str());
    const std::string diagnostics = cmd.output.empty() ? "" : diagnostics_output(cmd);
    const std::filesystem::path checkpoints = checkpoint_folder(cmd, scene);
    for (const std::string& path : {cmd.output, diagnostics})
        if (!path.empty()) remove_stale_temporaries_for(path, cmd.common.quiet);
    std::optional<TrajectoryWriter> out;
    if (!cmd.output.empty())
        out.emplace(cmd.output, diagnostics, scene, sim.estimate.estimator.get());
    const std::int64_t total = tl.end_step(); // the last row at t = duration
    // Checkpoints at frames K, 2K, ... of the video (frame k after k * steps_per_frame steps).
    const std::int64_t checkpoint_steps = std::int64_t{cmd.checkpoint_every} * tl.steps_per_frame;
    std::int64_t saved = 0;
    Progress progress("simulating", total, cmd.common.quiet);
    if (out) out->write(sim.model, sim.state);
    bool interrupted = false;
    for (std::int64_t k = 1; k <= total; ++k) {
        if (io::InterruptGuard::requested()) {
            interrupted = true;
            break;
        }
        sim.step();
        if (out && (k % cmd.every == 0 || k == total)) out->write(sim.model, sim.state);
        if (checkpoint_steps > 0 && k % checkpoint_steps == 0 &&
            k / tl.steps_per_frame < tl.frames) {
            save_checkpoint(checkpoints, scene, tl, sim, k / tl.steps_per_frame);
            ++saved;
        }
        progress.update(k);
    }
    progress.finish();
    std::vector<std::string> written;
    if (out) written = interrupted ? out->finish_interrupted() : out->finish();
    if (saved > 0)
        written.push_back(std::to_string(saved) + " checkpoint" + (saved == 1 ? "" : "s") + " in " +
                          checkpoints.string() + "/");
    report(cmd, scene, sim, tl.h, written, interrupted);
    return interrupted ? interrupted_exit_code(io::InterruptGuard::signal_number()) : kOk;
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
                  "<stem>.interrupted.csv");
    s->add_option("--diagnostics", cmd->diagnostics,
                  "diagnostics CSV (default <stem>.diagnostics.csv; none: do not write them)");
    s->add_option("--every", cmd->every, "write every N-th step (default 1)")
        ->check(CLI::PositiveNumber);
    s->add_option("--fps", cmd->fps,
                  "frames per second, as `tumble render --fps` (the step fits the frame times; "
                  "checkpoints are numbered by frame)")
        ->check(CLI::Range(1, 1000));
    s->add_option("--checkpoint-every", cmd->checkpoint_every,
                  "write the complete state every K frames (frames K, 2K, ...) for `tumble render "
                  "--frames A:B --from-checkpoints DIR` to continue from (docs/cluster.md)")
        ->check(CLI::PositiveNumber);
    s->add_option("--checkpoints", cmd->checkpoints,
                  "folder of the checkpoints (default <scene>_checkpoints/): DIR/frame_000060.tck");
    return {[s] { return s->parsed(); }, [cmd] { return run_simulate(*cmd); }};
}

} // namespace tumble::app
