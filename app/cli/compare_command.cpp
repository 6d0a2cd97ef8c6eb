// `tumble render --compare euler,rk4,...`: the same scene stepped by several integrators, drawn
// side by side in one video (app/run/compare_run.h, which the Python module runs too); here the
// command line's part: loading, the summary and the exit code.
#include "app/cli/compare_command.h"

#include "app/cli/failure.h"
#include "app/run/compare_run.h"
#include "io/interrupt.h"

#include <cstdio>

namespace tumble::app {
namespace {

void print_summary(const CompareRun& run) {
    for (const SideBySide::LaneResult& lane : run.lanes) {
        if (lane.diverged.empty())
            std::fprintf(stderr, "tumble: %s: energy %.9g J -> %.9g J\n", lane.integrator.c_str(),
                         lane.initial_energy, lane.energy);
        else
            std::fprintf(stderr, "tumble: %s diverged: %s\n", lane.integrator.c_str(),
                         lane.diverged.c_str());
        for (const std::string& line : lane.estimate)
            std::fprintf(stderr, "tumble: %s: %s\n", lane.integrator.c_str(), line.c_str());
    }
    std::fprintf(stderr, "tumble: wrote %s (%lld frames, %d x %d tiles of %dx%d)\n",
                 run.output.c_str(), static_cast<long long>(run.frames), run.cols, run.rows,
                 run.tile_width, run.tile_height);
    if (!run.sink_note.empty()) std::fprintf(stderr, "tumble: note: %s\n", run.sink_note.c_str());
}

} // namespace

int run_compare(const RenderCommand& cmd) {
    io::InterruptGuard guard; // from the start: no signal can leave the output half-written
    check_compare_request(cmd.common.run);
    const bool quiet = cmd.common.quiet;
    RenderRequest request = cmd;
    request.quiet = quiet;
    const CompareRun run =
        render_compare(load_for_command(cmd.common), request, cmd.common.threads, quiet,
                       [quiet](const std::string& n) {
                           if (!quiet) std::fprintf(stderr, "tumble: note: %s\n", n.c_str());
                       });
    if (!quiet) print_summary(run);
    if (run.interrupted) return interrupted_exit_code(io::InterruptGuard::signal_number());
    return kOk;
}

} // namespace tumble::app
