// `tumble sweep`: one scene per combination of --set values and a manifest (app/cluster/sweep.h),
// to render as a Slurm array job (scripts/slurm/render-sweep.sbatch) or in any loop.
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/cluster/sweep.h"
#include "io/interrupt.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace tumble::app {
namespace {

struct SweepCommand {
    std::string scene;
    std::vector<std::string> sets;
    std::string output;
    bool quiet = false;
};

int run_sweep(const SweepCommand& cmd) {
    io::InterruptGuard guard; // Ctrl-C: stops between scenes, leaving nothing
    const Sweep sweep = make_sweep(cmd.scene, cmd.sets);
    write_sweep(sweep, cmd.output);
    if (!cmd.quiet)
        std::fprintf(stderr, "tumble: %s: %zu scene%s and manifest.json written to %s\n",
                     sweep.source.c_str(), sweep.scenes.size(), sweep.scenes.size() == 1 ? "" : "s",
                     cmd.output.c_str());
    return kOk;
}

} // namespace

Subcommand add_sweep_command(CLI::App& app) {
    auto cmd = std::make_shared<SweepCommand>();
    CLI::App* s = app.add_subcommand(
        "sweep", "write one scene per combination of --set values, and a manifest");
    s->add_option("scene", cmd->scene,
                  "scene file, or a built-in scene name (default: the built-in default)");
    s->add_option("--set", cmd->sets,
                  "PATH=V1,V2,...: a scene field (world.integrator, bodies.1.angular_velocity or "
                  "/world/dt) and its values (JSON; a word is a string); repeat for more fields")
        ->required()
        ->allow_extra_args(false); // one PATH=VALUES per --set; commas stay in the values
    s->add_option("-o,--output", cmd->output,
                  "the folder to create (scene_000.json ..., "
                  "manifest.json)")
        ->required();
    s->add_flag("-q,--quiet", cmd->quiet, "no summary");
    return {[s] { return s->parsed(); }, [cmd] { return run_sweep(*cmd); }};
}

} // namespace tumble::app
