// `tumble render`: step the scene and draw frame k at exactly t = k / fps into a video, a PNG
// sequence or a single still.
// The frames go through the pipeline of app/run/pipeline.h (physics, render and output on their
// own threads); --stats prints each stage's rate. With --compare, compare_command.cpp draws
// several integrators side by side instead.
#include "app/cli/compare_command.h"
#include "app/cli/failure.h"
#include "app/cli/render_setup.h"
#include "app/cli/shard_setup.h"
#include "app/cli/subcommand.h"
#include "app/run/accuracy_choice.h"
#include "app/run/auto_camera.h"
#include "app/run/peak_memory.h"
#include "app/run/prepare_run.h"
#include "app/run/render_frames.h"
#include "app/run/run_estimate.h"
#include "io/bad_input.h"
#include "io/interrupt.h"
#include "physics/diagnostics.h"

#include <chrono>
#include <cstdio>
#include <memory>

namespace tumble::app {
namespace {

void add_render_options(CLI::App* r, RenderCommand& render) {
    add_scene_options(r, render.common);
    add_error_estimate_options(r, render.common);
    r->add_option("-o,--output", render.output,
                  "out.mp4 | out.webm | out.gif | frames/ | frames/%06d.png | still.png (default: "
                  "<scene>.mp4)");
    r->add_option("--width", render.width, "image width, pixels (even for MP4)");
    r->add_option("--height", render.height, "image height, pixels (even for MP4)");
    r->add_option("--fps", render.fps, "frames per second");
    auto* frame =
        r->add_option("--frame", render.frame, "render only frame K (t = K / fps) to a .png still");
    auto* time = r->add_option(
        "--time", render.time,
        "render only the frame shown at t = SECONDS (the nearest frame) to a .png still");
    time->excludes(frame);
    r->add_option("--frames", render.frames,
                  "render only frames A to B-1 of the run, a shard (A:B; for .mp4 on key frames, "
                  "every 2 s); join MP4 shards with `tumble join`")
        ->excludes(frame)
        ->excludes(time);
    r->add_option("--from-checkpoints", render.from_checkpoints,
                  "continue from the nearest checkpoint at or before the first frame, written by "
                  "`tumble simulate --checkpoint-every K --checkpoints DIR`");
    r->add_option(
         "--crf", render.crf,
         "quality, lower is better: H.264 (.mp4) 0..51, VP9 (.webm) 0..63 (checked by the sink)")
        ->check(CLI::Range(0, 63));
    r->add_option(
        "--preset", render.preset,
        "encoder preset, ultrafast .. veryslow (default medium; ultrafast with --preview)");
    r->add_flag(
        "--preview", render.preview,
        "quick look: 640x360, no shadows, anti-aliasing, AO or reflections (explicit options "
        "still apply)");
}

// On/off pairs that override the scene's render settings only when given.
void add_switches(CLI::App* r, RenderCommand& render) {
    auto on_off = [r](const char* name, std::optional<bool>& value, const std::string& what) {
        r->add_flag_callback(
            std::string("--") + name, [&value] { value = true; }, what + " (default: the scene's)");
        r->add_flag_callback(
            std::string("--no-") + name, [&value] { value = false; },
            std::string("turn --") + name + " off");
    };
    on_off("shadows", render.shadows, "shadows from the key light");
    on_off("soft-shadows", render.soft_shadows,
           "shadow edges that harden towards the contact (the light's angle sets how soft)");
    on_off("ao", render.ambient_occlusion,
           "ambient occlusion: bodies darken the ground and each other where they meet");
    on_off("reflections", render.reflections, "the bodies mirrored in a polished ground");
    on_off("aa", render.antialiasing, "4x multisample anti-aliasing");
    on_off("overlay", render.overlay,
           "time, step, integrator, energy and momentum in the top-left corner");
    on_off("axes", render.axes, "each body's x, y, z axes drawn red, green, blue");
    on_off("vectors", render.vectors,
           "arrows for each body's angular velocity w (amber) and angular momentum L (cyan)");
    r->add_option("--chart", render.chart,
                  "strip charts in the frame, one per quantity: " + quantity_names())
        ->delimiter(',');
    r->add_option("--chart-body", render.chart_body,
                  "chart this body's quantities instead of the scene's sums (name or index)");
    r->add_option("--chart-window", render.chart_window,
                  "seconds of time the charts show, rolling (default: the whole run)")
        ->check(CLI::NonNegativeNumber);
    on_off("trails", render.trails, "the path of each moving body's centre of mass, fading");
    r->add_option("--trail-seconds", render.trail_seconds, "length of the trails (default 3 s)")
        ->check(CLI::PositiveNumber);
    r->add_option("--trail-axis", render.trail_axis,
                  "also trace the tip of this body axis: x, y or z (implies --trails)");
    r->add_option("--poinsot", render.poinsot,
                  "Poinsot's construction for this torque-free body: its energy ellipsoid rolling "
                  "on the invariable plane, with the polhode and herpolhode, framed by the camera "
                  "unless --camera is given (a warning if the body may feel a torque)");
    r->add_option("--camera", render.camera,
                  "the camera: X,Y,Z:X,Y,Z[:FOV] (position:target[:field of view, degrees]), "
                  "auto (every moving body in view) or poinsot (the construction)");
    r->add_option("--overlay-body", render.overlay_body,
                  "the overlay shows this body's energy and momentum instead of the scene's sums");
    r->add_flag("--stats", render.stats, "print the frame rate of each pipeline stage");
    r->add_flag("--overwrite", render.overwrite,
                "a PNG folder holding frames of an earlier run: remove those frames first "
                "(only files named like the pattern; refused otherwise)");
    r->add_option("--compare", render.compare,
                  "integrators to draw side by side, e.g. euler,symplectic_euler,rk4,splitting")
        ->delimiter(',');
}

void print_summary(const RenderCommand& cmd, const Scene& scene, const Timeline& tl,
                   const Simulation& sim, const physics::Diagnostics& d0, const RunResult& r,
                   const render::FrameSink& sink, double wall) {
    if (cmd.common.quiet) return;
    const physics::Diagnostics d1 = physics::diagnose(sim.model, sim.state);
    if (cmd.frame) // a still: its own frame, not the whole video's
        std::fprintf(
            stderr, "tumble: %s: frame %lld at t = %.9g s, %d step%s of %.9g s per frame\n",
            scene.source.c_str(), static_cast<long long>(*cmd.frame), tl.frame_time(*cmd.frame),
            tl.steps_per_frame, tl.steps_per_frame == 1 ? "" : "s", tl.h);
    else
        std::fprintf(stderr, "tumble: %s: %s%s%s\n", scene.source.c_str(),
                     cmd.frames ? "frames " : "", cmd.frames ? cmd.frames->c_str() : "",
                     (cmd.frames ? " of " + tl.describe() : tl.describe()).c_str());
    std::fprintf(stderr,
                 "tumble: integrator %s, %d bodies, t_end = %.6g s, energy %.9g J -> %.9g J\n",
                 std::string(physics::integrator_info(sim.model.integrator).name).c_str(),
                 sim.model.body_count(), sim.state.time(sim.model), d0.energy(), d1.energy());
    std::fprintf(stderr, "tumble: %lld frame%s in %.2f s wall (%.1f frames/s), %s\n",
                 static_cast<long long>(r.frames), r.frames == 1 ? "" : "s", wall,
                 wall > 0 ? r.frames / wall : 0.0, describe_peak_memory().c_str());
    for (const std::string& line : describe_choice(scene, true))
        std::fprintf(stderr, "tumble: %s\n", line.c_str());
    for (const std::string& line : estimate_summary(sim))
        std::fprintf(stderr, "tumble: %s\n", line.c_str());
    if (const std::string e = effort_summary(sim); !e.empty())
        std::fprintf(stderr, "tumble: %s\n", e.c_str());
    report_tolerance(scene, sim);
    std::fprintf(stderr, "tumble: wrote %s\n", sink.describe().c_str());
    if (!sink.note().empty()) std::fprintf(stderr, "tumble: note: %s\n", sink.note().c_str());
}

int run_render(const RenderCommand& command) {
    if (!command.compare.empty() && (command.frames || !command.from_checkpoints.empty()))
        throw io::BadInput("--compare draws whole runs side by side: it takes no --frames or "
                           "--from-checkpoints");
    if (!command.compare.empty()) return run_compare(command);
    RenderCommand cmd = command;
    cmd.quiet = cmd.common.quiet;
    // From the start: auto's pilots and camera.auto's pre-pass stop on Ctrl-C too, and no signal
    // can leave the output half-written (on an exception the sink's destructor deletes it).
    io::InterruptGuard guard;
    Scene loaded = load_for_command(cmd.common);
    apply_render_overrides(cmd, loaded);
    PreparedRun run = prepare_run(std::move(loaded), {cmd.common.threads});
    Scene& scene = run.scene;
    const Timeline& tl = run.timeline;
    Simulation& sim = run.sim;
    if (const std::string note = resolve_time(cmd, tl); !note.empty() && !cmd.common.quiet)
        std::fprintf(stderr, "tumble: note: %s\n", note.c_str());
    check_frame_index(cmd, tl);
    const FrameRange range = render_range(cmd, scene, tl); // --frames A:B, or the whole run
    const std::string output = output_name(cmd, scene);
    if (const std::string note = threads_note(sim, cmd.common.threads);
        !note.empty() && !cmd.common.quiet)
        std::fprintf(stderr, "tumble: note: %s\n", note.c_str());
    // Checked before the output exists: a checkpoint of another run is refused leaving nothing.
    const std::optional<ResumePoint> resume = resume_point(cmd, scene, tl, sim, range);
    if (resume && sim.estimate.estimator && scene.error_estimate.only_for_tolerance) {
        sim.estimate = {}; // the shadow run starts at t = 0: nothing to check the tolerance with
        if (!cmd.common.quiet)
            std::fprintf(stderr, "tumble: note: the tolerance is not checked in a render continued "
                                 "from a checkpoint (the check follows the run from t = 0: "
                                 "`tumble simulate` of this scene makes it)\n");
    }
    if (resume && sim.estimate.estimator)
        throw io::BadInput("--from-checkpoints: the error estimate (--error-estimate or "
                           "world.error_estimate) steps a second run at h/2 from t = 0, which a "
                           "checkpoint does not hold; render without --from-checkpoints, or with "
                           "--no-error-estimate");
    const std::unique_ptr<render::FrameSink> sink = open_render_sink(
        cmd, scene, output, run_output(cmd, scene, tl, range, output), cmd.common.quiet);
    // camera.auto: a pre-pass over the run, once the input and the output are known to be good
    // (a bad output name is exit 2 before any stepping).
    frame_automatically(scene, tl, cmd.common.quiet);
    const physics::Diagnostics d0 = physics::diagnose(sim.model, sim.state);
    const auto t0 = std::chrono::steady_clock::now();
    const RunResult r = render_frames(scene, tl, sim, *sink, range.first, range.end - 1,
                                      cmd.common.quiet, resume ? &*resume : nullptr);
    if (r.frames > 0)
        sink->finish();
    else
        sink->abort(); // interrupted before the first frame: nothing worth keeping
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    print_summary(cmd, scene, tl, sim, d0, r, *sink, wall);
    if (cmd.stats) std::fprintf(stderr, "%s", describe_stats(r.stats).c_str());
    if (!r.interrupted) return kOk;
    std::fprintf(stderr,
                 "tumble: interrupted by signal %d after %lld frames; %s is complete and plays\n",
                 io::InterruptGuard::signal_number(), static_cast<long long>(r.frames),
                 sink->describe().c_str());
    return interrupted_exit_code(io::InterruptGuard::signal_number());
}

} // namespace

Subcommand add_render_command(CLI::App& app) {
    auto cmd = std::make_shared<RenderCommand>();
    CLI::App* r = app.add_subcommand(
        "render", "simulate a scene and render it to MP4, PNG frames or a still");
    add_render_options(r, *cmd);
    add_switches(r, *cmd);
    return {[r] { return r->parsed(); }, [cmd] { return run_render(*cmd); }};
}

} // namespace tumble::app
