// `tumble render --compare euler,rk4,...`: the same scene stepped by several integrators, drawn
// side by side in one video (app/run/side_by_side.h). The overlay is on unless --no-overlay: it
// names the integrator and shows its energy drift since t = 0.
//
// Frames are made in a plain loop (simulate, draw each tile, write), not the threaded pipeline of
// app/run/pipeline.h: a comparison is for looking at, not for speed.
#include "app/cli/compare_command.h"

#include "app/cli/failure.h"
#include "app/run/auto_camera.h"
#include "app/run/interrupt.h"
#include "app/run/progress.h"
#include "app/run/render_frames.h"
#include "app/run/side_by_side.h"
#include "app/scene/scene_error.h"

#include <algorithm>
#include <cstdio>

namespace tumble::app {
namespace {

std::vector<physics::Integrator> parse_methods(const std::vector<std::string>& names) {
    std::vector<physics::Integrator> out;
    for (const std::string& name : names) {
        const auto id = physics::integrator_from_name(name);
        if (!id)
            throw SceneError("--compare", name,
                             "unknown integrator; valid integrators: " +
                                 physics::integrator_names());
        if (std::find(out.begin(), out.end(), *id) != out.end())
            throw SceneError("--compare", name, "each integrator may appear once");
        out.push_back(*id);
    }
    if (out.size() < 2 || out.size() > 9)
        throw SceneError("--compare", std::to_string(out.size()) + " integrators",
                         "expected 2 to 9 names separated by commas");
    return out;
}

void print_summary(const SideBySide& tiles, const render::FrameSink& sink, std::int64_t written) {
    for (const SideBySide::LaneResult& lane : tiles.results()) {
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
                 sink.describe().c_str(), static_cast<long long>(written), tiles.cols(),
                 tiles.rows(), tiles.tile_width(), tiles.tile_height());
    if (!sink.note().empty()) std::fprintf(stderr, "tumble: note: %s\n", sink.note().c_str());
}

} // namespace

int run_compare(const RenderCommand& command) {
    RenderCommand cmd = command;
    if (cmd.common.integrator)
        throw SceneError("--integrator", *cmd.common.integrator,
                         "not with --compare, which names the integrators itself");
    Scene scene = load_for_command(cmd.common);
    apply_render_overrides(cmd, scene);
    if (!cmd.overlay) scene.render.overlay = true; // each tile is labelled by its overlay
    const auto methods = parse_methods(cmd.compare);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    if (const std::string note = resolve_time(cmd, tl); !note.empty() && !cmd.common.quiet)
        std::fprintf(stderr, "tumble: note: %s\n", note.c_str());
    check_frame_index(cmd, tl);
    const std::int64_t first = cmd.frame.value_or(0), last = cmd.frame.value_or(tl.frames - 1);
    tune_allocator_for_rendering();
    InterruptGuard guard; // from before the output exists: no signal can leave it half-written
    const std::unique_ptr<render::FrameSink> sink =
        open_render_sink(cmd, scene, output_name(cmd, scene, "-compare"));
    frame_automatically(scene, tl); // camera.auto, once input and output are known to be good
    SideBySide tiles(scene, methods, tl, cmd.common.threads, first, last);
    render::Image frame;
    Progress progress("comparing", last - first + 1, cmd.common.quiet);
    std::int64_t written = 0;
    for (std::int64_t k = first; k <= last && !InterruptGuard::requested(); ++k) {
        tiles.draw_next(frame);
        sink->write(frame);
        progress.update(++written);
    }
    progress.finish();
    if (written > 0)
        sink->finish();
    else
        sink->abort(); // interrupted before the first frame: nothing worth keeping
    if (!cmd.common.quiet) print_summary(tiles, *sink, written);
    if (InterruptGuard::requested()) return interrupted_exit_code(InterruptGuard::signal_number());
    return kOk;
}

} // namespace tumble::app
