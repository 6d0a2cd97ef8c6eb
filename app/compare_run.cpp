// `tumble render --compare euler,rk4,...`: the same scene stepped by several integrators, drawn
// side by side in one video, so that what each method does to the same motion can be seen
// frame by frame (a book's flip arriving early or late, energy drifting, a spin axis wandering).
//
// Each integrator runs its own Simulation of the scene from the same initial state and time
// step; every frame, each is drawn by one Renderer at the tile's size and copied into its tile
// of a grid (1 x 2 for two, 2 x 2 for up to four, 3 x 2 for six, 3 x 3 for nine), with a dark
// gutter of kGutter pixels between tiles. The overlay is
// on unless --no-overlay: it names the integrator and shows its energy drift since t = 0.
//
// A tile is exactly the picture `tumble render --integrator NAME` draws at the tile's size
// (tested), so the comparison hides nothing. A method that diverges stops there: its tile keeps
// the last frame it drew, darkened, and the summary names the step; the others go on.
//
// Frames are made in a plain loop (simulate, draw each tile, write), not the threaded pipeline of
// app/pipeline.h: a comparison is for looking at, not for speed.
#include "app/commands.h"
#include "app/frame_source.h"
#include "app/interrupt.h"
#include "app/progress.h"
#include "app/render_run.h"
#include "app/scene_error.h"
#include "app/scene_options.h"
#include "app/simulation.h"
#include "app/timeline.h"
#include "physics/step.h"
#include "render/frame_sink.h"
#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace tumble::app {
namespace {

constexpr int kGutter = 2;                // pixels between tiles
constexpr std::uint8_t kGutterShade = 24; // their grey level

// Columns and rows for n tiles: as square as possible, wider than tall.
struct Grid {
    int cols, rows;
};
Grid grid_for(int n) {
    const int cols = static_cast<int>(std::ceil(std::sqrt(double(n))));
    const int rows = (n + cols - 1) / cols;
    return {cols, rows};
}

// One method under comparison: its own scene copy (integrator set), simulation and frames.
struct Lane {
    Scene scene;
    Simulation sim;
    std::unique_ptr<FrameSource> frames;
    render::SceneView view;
    render::Image tile;
    std::string diverged; // the DivergenceError's message, once it has happened
};

void copy_tile(const render::Image& tile, render::Image& out, int x0, int y0) {
    for (int y = 0; y < tile.height; ++y)
        std::memcpy(out.row(y0 + y) + 3 * x0, tile.row(y), std::size_t(tile.width) * 3);
}

void darken(render::Image& image) {
    for (std::uint8_t& c : image.rgb) c = static_cast<std::uint8_t>(c / 3);
}

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

} // namespace

int run_compare(const RenderCommand& cmd) {
    Scene base;
    Timeline tl;
    std::vector<Lane> lanes;
    Grid grid{};
    try {
        if (cmd.common.integrator)
            throw SceneError("--integrator", *cmd.common.integrator,
                             "not with --compare, which names the integrators itself");
        base = load_for_command(cmd.common);
        apply_render_overrides(cmd, base);
        if (!cmd.overlay) base.render.overlay = true; // each tile is labelled by its overlay
        const auto methods = parse_methods(cmd.compare);
        grid = grid_for(int(methods.size()));
        tl = make_timeline(base.world.dt, base.duration, base.render.fps);
        check_frame_index(cmd, tl);
        lanes.resize(methods.size());
        for (std::size_t i = 0; i < methods.size(); ++i) {
            lanes[i].scene = base;
            lanes[i].scene.world.integrator = methods[i];
            lanes[i].sim = make_simulation(lanes[i].scene, tl.h, cmd.common.threads);
        }
    } catch (const SceneError& e) {
        return report_error(e.what(), kBadInput);
    }
    const int tile_w = (base.render.width - (grid.cols - 1) * kGutter) / grid.cols;
    const int tile_h = (base.render.height - (grid.rows - 1) * kGutter) / grid.rows;
    if (tile_w < 16 || tile_h < 16)
        return report_error("--compare: tiles of " + std::to_string(tile_w) + "x" +
                                std::to_string(tile_h) +
                                " pixels are too small; give a larger --width/--height",
                            kBadInput);
    const std::string output = output_name(cmd, base, "-compare");
    if (const std::string problem = output_problem(cmd, output); !problem.empty())
        return report_error(problem, kBadInput);
    std::unique_ptr<render::FrameSink> sink;
    try {
        const std::int64_t first = cmd.frame.value_or(0), last = cmd.frame.value_or(tl.frames - 1);
        for (Lane& lane : lanes)
            lane.frames = std::make_unique<FrameSource>(lane.scene, tl, lane.sim, first, last);
        sink = open_render_sink(cmd, base, output);
        RenderSettings tile_settings = base.render;
        tile_settings.width = tile_w;
        tile_settings.height = tile_h;
        tune_allocator_for_rendering();
        render::Renderer renderer(render_options(tile_settings));
        render::Image frame(base.render.width, base.render.height);
        std::fill(frame.rgb.begin(), frame.rgb.end(), kGutterShade);
        InterruptGuard guard;
        Progress progress("comparing", last - first + 1, cmd.common.quiet);
        std::int64_t written = 0;
        for (std::int64_t k = first; k <= last && !InterruptGuard::requested(); ++k) {
            for (std::size_t i = 0; i < lanes.size(); ++i) {
                Lane& lane = lanes[i];
                if (lane.diverged.empty()) {
                    try {
                        lane.frames->next(lane.view);
                        renderer.draw(lane.view, lane.tile);
                    } catch (const physics::DivergenceError& e) {
                        lane.diverged = e.what();
                        if (lane.tile.width == 0) lane.tile = render::Image(tile_w, tile_h);
                        darken(lane.tile);
                    }
                }
                const int col = int(i) % grid.cols, row = int(i) / grid.cols;
                copy_tile(lane.tile, frame, col * (tile_w + kGutter), row * (tile_h + kGutter));
            }
            sink->write(frame);
            progress.update(++written);
        }
        progress.finish();
        if (written > 0)
            sink->finish();
        else
            sink->abort(); // interrupted before the first frame: nothing worth keeping
        if (!cmd.common.quiet) {
            for (const Lane& lane : lanes) {
                const auto name = physics::integrator_info(lane.sim.model.integrator).name;
                if (lane.diverged.empty())
                    std::fprintf(stderr, "tumble: %s: energy %.9g J -> %.9g J\n",
                                 std::string(name).c_str(), lane.frames->initial().energy(),
                                 physics::diagnose(lane.sim.model, lane.sim.state).energy());
                else
                    std::fprintf(stderr, "tumble: %s diverged: %s\n", std::string(name).c_str(),
                                 lane.diverged.c_str());
            }
            std::fprintf(stderr, "tumble: wrote %s (%lld frames, %d x %d tiles of %dx%d)\n",
                         sink->describe().c_str(), static_cast<long long>(written), grid.cols,
                         grid.rows, tile_w, tile_h);
        }
        if (InterruptGuard::requested()) return 128 + InterruptGuard::signal_number();
        return kOk;
    } catch (const render::SinkError& e) {
        if (sink) sink->abort();
        return report_error(e.what(), kBadInput);
    } catch (const std::exception& e) {
        if (sink) sink->abort();
        return report_error(e.what(), kRunFailed);
    }
}

} // namespace tumble::app
