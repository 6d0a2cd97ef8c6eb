// `tumble render`: step the scene and draw frame k at exactly t = k / fps into a video, a PNG
// sequence or a single still.
// The frames go through the pipeline of app/pipeline.h (physics, render and output on their own
// threads); --stats prints each stage's rate.
#include "app/commands.h"
#include "app/interrupt.h"
#include "app/render_run.h"
#include "app/scene_error.h"
#include "app/scene_options.h"
#include "app/simulation.h"
#include "app/timeline.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "render/frame_sink.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace tumble::app {
namespace {

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
    if (!cmd.compare.empty()) return run_compare(cmd);
    Scene scene;
    Timeline tl;
    Simulation sim;
    std::unique_ptr<render::FrameSink> sink;
    try {
        scene = load_for_command(cmd.common);
        apply_render_overrides(cmd, scene);
        tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
        check_frame_index(cmd, tl);
        sim = make_simulation(scene, tl.h, cmd.common.threads);
    } catch (const SceneError& e) {
        return report_error(e.what(), kBadInput);
    }
    if (const std::string note = threads_note(sim, cmd.common.threads);
        !note.empty() && !cmd.common.quiet)
        std::fprintf(stderr, "tumble: note: %s\n", note.c_str());
    const std::string output = output_name(cmd, scene);
    if (const std::string problem = output_problem(cmd, output); !problem.empty())
        return report_error(problem, kBadInput);
    try {
        sink = open_render_sink(cmd, scene, output);
        InterruptGuard guard;
        const physics::Diagnostics d0 = physics::diagnose(sim.model, sim.state);
        const auto t0 = std::chrono::steady_clock::now();
        const RunResult r = render_frames(scene, tl, sim, *sink, cmd.frame.value_or(0),
                                          cmd.frame.value_or(tl.frames - 1), cmd.common.quiet);
        if (r.frames > 0)
            sink->finish();
        else
            sink->abort(); // interrupted before the first frame: nothing worth keeping
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        print_summary(cmd, scene, tl, sim, d0, r, *sink, wall);
        if (cmd.stats) std::fprintf(stderr, "%s", describe_stats(r.stats).c_str());
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
