// `tumble render`: step the scene and draw frame k at exactly t = k / fps into a video, a PNG
// sequence or a single still.
#include "app/commands.h"
#include "app/interrupt.h"
#include "app/progress.h"
#include "app/scene_error.h"
#include "app/scene_options.h"
#include "app/simulation.h"
#include "app/timeline.h"
#include "app/view_builder.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "render/frame_sink.h"
#include "render/renderer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace tumble::app {
namespace {

std::string default_output(const Scene& scene) {
    std::string stem = std::filesystem::path(scene.source).stem().string();
    return (stem.empty() ? "tumble" : stem) + ".mp4";
}

void apply_render_overrides(const RenderCommand& cmd, Scene& scene) {
    if (cmd.width) scene.render.width = *cmd.width;
    if (cmd.height) scene.render.height = *cmd.height;
    if (cmd.fps) scene.render.fps = *cmd.fps;
    if (scene.render.width < 16 || scene.render.height < 16)
        throw SceneError("--width/--height",
                         std::to_string(scene.render.width) + "x" +
                             std::to_string(scene.render.height),
                         "expected at least 16x16 pixels");
    if (scene.render.fps < 1)
        throw SceneError("--fps", std::to_string(scene.render.fps), "expected at least 1");
}

struct RunResult {
    std::int64_t frames = 0;
    bool interrupted = false;
};

// The frame loop: draw frame k, hand it to the sink, then step to frame k + 1.
RunResult render_frames(const Scene& scene, const Timeline& tl, Simulation& sim,
                        render::Renderer& renderer, render::FrameSink& sink,
                        std::optional<std::int64_t> only_frame, bool quiet) {
    render::SceneView view;
    render::Image image;
    RunResult out;
    const std::int64_t first = only_frame.value_or(0);
    const std::int64_t last = only_frame ? *only_frame : tl.frames - 1;
    Progress progress("rendering", last - first + 1, quiet);
    for (std::int64_t k = 0; k <= last; ++k) {
        if (InterruptGuard::requested()) {
            out.interrupted = true;
            break;
        }
        if (k >= first) {
            build_view(scene, sim.model, sim.state, view);
            renderer.draw(view, image);
            sink.write(image);
            ++out.frames;
            progress.update(k - first + 1);
        }
        if (k < last)
            for (int s = 0; s < tl.steps_per_frame; ++s) physics::step(sim.model, sim.state);
    }
    progress.finish();
    return out;
}

void print_summary(const RenderCommand& cmd, const Scene& scene, const Timeline& tl,
                   const Simulation& sim, const physics::Diagnostics& d0, const RunResult& r,
                   const render::FrameSink& sink, double wall) {
    if (cmd.common.quiet) return;
    const physics::Diagnostics d1 = physics::diagnose(sim.model, sim.state);
    std::fprintf(stderr, "tumble: %s: %s\n", scene.source.c_str(), tl.describe().c_str());
    std::fprintf(stderr,
                 "tumble: integrator %s, %d bodies, t_end = %.6g s, energy %.9g J -> %.9g J\n",
                 std::string(physics::integrator_info(sim.model.integrator).name).c_str(),
                 sim.model.body_count(), sim.state.time(sim.model), d0.energy(), d1.energy());
    std::fprintf(stderr, "tumble: %lld frames in %.2f s wall (%.1f frames/s)\n",
                 static_cast<long long>(r.frames), wall, wall > 0 ? r.frames / wall : 0.0);
    std::fprintf(stderr, "tumble: wrote %s\n", sink.describe().c_str());
}

} // namespace

int run_render(const RenderCommand& cmd) {
    Scene scene;
    Timeline tl;
    Simulation sim;
    std::unique_ptr<render::FrameSink> sink;
    try {
        scene = load_for_command(cmd.common);
        apply_render_overrides(cmd, scene);
        tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
        if (cmd.frame && (*cmd.frame < 0 || *cmd.frame >= tl.frames))
            throw SceneError("--frame", std::to_string(*cmd.frame),
                             "expected a frame index in [0, " + std::to_string(tl.frames - 1) +
                                 "]");
        sim = make_simulation(scene, tl.h);
    } catch (const SceneError& e) {
        return report_error(e.what(), kBadInput);
    }
    const std::string output = cmd.output.empty() ? default_output(scene) : cmd.output;
    if (cmd.frame && !output.ends_with(".png"))
        return report_error("--frame renders one still: the output must end in .png, got " + output,
                            kBadInput);
    try {
        render::Renderer renderer({scene.render.width, scene.render.height});
        const auto parent = std::filesystem::path(output).parent_path();
        if (!parent.empty() && output.find('%') == std::string::npos)
            std::filesystem::create_directories(parent);
        render::SinkOptions sink_options;
        sink_options.width = scene.render.width;
        sink_options.height = scene.render.height;
        sink_options.fps = scene.render.fps;
        sink_options.crf = cmd.crf;
        sink_options.preset = cmd.preset;
        sink = render::open_sink(output, sink_options);
        InterruptGuard guard;
        const physics::Diagnostics d0 = physics::diagnose(sim.model, sim.state);
        const auto t0 = std::chrono::steady_clock::now();
        const RunResult r =
            render_frames(scene, tl, sim, renderer, *sink, cmd.frame, cmd.common.quiet);
        if (r.frames > 0)
            sink->finish();
        else
            sink->abort(); // interrupted before the first frame: nothing worth keeping
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        print_summary(cmd, scene, tl, sim, d0, r, *sink, wall);
        if (r.interrupted) {
            std::fprintf(
                stderr,
                "tumble: interrupted by signal %d after %lld frames; %s is complete and plays\n",
                InterruptGuard::signal_number(), static_cast<long long>(r.frames),
                sink->describe().c_str());
            return 128 + InterruptGuard::signal_number();
        }
        return kOk;
    } catch (const physics::DivergenceError& e) {
        if (sink) sink->abort();
        return report_error(scene.source + ": " + e.what(), kRunFailed);
    } catch (const render::SinkError& e) {
        if (sink) sink->abort();
        return report_error(e.what(), kBadInput);
    } catch (const std::exception& e) {
        if (sink) sink->abort();
        return report_error(e.what(), kRunFailed);
    }
}

} // namespace tumble::app
