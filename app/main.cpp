// tumble: rigid bodies stepped by a small exact physics core, drawn headlessly with OSMesa.
#include "app/commands.h"
#include "render/frame_sink.h"

#include <CLI/CLI.hpp>

#include <cstdio>

namespace {

using namespace tumble::app;

void add_scene_options(CLI::App* cmd, SceneOptions& o) {
    cmd->add_option("scene", o.scene,
                    "scene file, or a built-in scene name (default: the built-in default)");
    cmd->add_option("--integrator", o.integrator, "override the scene's integrator");
    cmd->add_option("--duration", o.duration, "override the scene's duration, s");
    cmd->add_option("--dt", o.dt, "override the scene's time step, s");
    cmd->add_option("--threads", o.threads,
                    "physics threads for contacts (default 1; the states are identical for any "
                    "count)")
        ->check(CLI::Range(1, 64));
    cmd->add_flag("-q,--quiet", o.quiet, "no progress bar and no summary");
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"tumble: rigid-body dynamics rendered headlessly to video or PNG"};
    app.require_subcommand(0, 1);
    bool version = false;
    app.add_flag("--version", version, "print the version and the OpenGL renderer, then exit");

    RenderCommand render;
    CLI::App* r = app.add_subcommand(
        "render", "simulate a scene and render it to MP4, PNG frames or a still");
    add_scene_options(r, render.common);
    r->add_option("-o,--output", render.output,
                  "out.mp4 | frames/ | frames/%06d.png | still.png (default: <scene>.mp4)");
    r->add_option("--width", render.width, "image width, pixels (even for MP4)");
    r->add_option("--height", render.height, "image height, pixels (even for MP4)");
    r->add_option("--fps", render.fps, "frames per second");
    r->add_option("--frame", render.frame, "render only frame K (t = K / fps) to a .png still");
    r->add_option(
         "--crf", render.crf,
         "quality, lower is better: H.264 (.mp4) 0..51, VP9 (.webm) 0..63 (checked by the sink)")
        ->check(CLI::Range(0, 63));
    r->add_option(
        "--preset", render.preset,
        "encoder preset, ultrafast .. veryslow (default veryfast; ultrafast with --preview)");
    r->add_flag("--preview", render.preview,
                "quick look: 640x360, no shadows, no anti-aliasing (explicit options still apply)");
    // On/off pairs that override the scene's render settings only when given.
    auto on_off = [r](const char* name, std::optional<bool>& value, const std::string& what) {
        r->add_flag_callback(
            std::string("--") + name, [&value] { value = true; }, what + " (default: the scene's)");
        r->add_flag_callback(
            std::string("--no-") + name, [&value] { value = false; },
            std::string("turn --") + name + " off");
    };
    on_off("shadows", render.shadows, "shadows from the key light");
    on_off("aa", render.antialiasing, "4x multisample anti-aliasing");
    on_off("overlay", render.overlay,
           "time, step, integrator, energy and momentum in the top-left corner");
    on_off("axes", render.axes, "each body's x, y, z axes drawn red, green, blue");
    on_off("vectors", render.vectors,
           "arrows for each body's angular velocity w (amber) and angular momentum L (cyan)");
    r->add_flag("--stats", render.stats, "print the frame rate of each pipeline stage");
    r->add_option("--compare", render.compare,
                  "integrators to draw side by side, e.g. euler,symplectic_euler,rk4,splitting")
        ->delimiter(',');

    BenchRenderCommand bench;
    CLI::App* b = app.add_subcommand(
        "bench-render", "frame rates per pipeline stage and end to end, against a null sink");
    b->add_option("cases", bench.cases, "cases to run (default: all; see bench/README.md)");
    b->add_option("--repeats", bench.repeats, "runs per case; the table shows medians (default 3)")
        ->check(CLI::PositiveNumber);
    b->add_option("--csv", bench.csv, "append the results to this CSV file");
    b->add_option("--machine", bench.machine, "machine label in the CSV (default: host name)");
    b->add_flag("--quick", bench.quick, "fewer frames per case");

    SimulateCommand simulate;
    CLI::App* s = app.add_subcommand(
        "simulate", "step a scene without rendering; write states and diagnostics as CSV");
    add_scene_options(s, simulate.common);
    s->add_option("-o,--output", simulate.output,
                  "states CSV (diagnostics go to <stem>.diagnostics.csv)")
        ->required();
    s->add_option("--every", simulate.every, "write every N-th step (default 1)")
        ->check(CLI::PositiveNumber);

    SceneOptions explain;
    CLI::App* e =
        app.add_subcommand("explain", "print the model that will run and which stages are on");
    add_scene_options(e, explain);

    app.add_subcommand("scenes", "list the built-in scenes");

    GoldensCommand goldens;
    CLI::App* g =
        app.add_subcommand("goldens", "check or update golden images listed in a manifest");
    g->add_option("action", goldens.action, "check | update")
        ->required()
        ->check(CLI::IsMember({"check", "update"}));
    g->add_option("manifest", goldens.manifest,
                  "golden manifest JSON (e.g. tests/goldens/goldens.json)")
        ->required();
    g->add_option("--artifacts", goldens.artifacts,
                  "folder for actual and diff images of failures");
    g->add_flag("--force", goldens.force,
                "update even when the goldens were made by another GL renderer");
    g->add_flag("--add-missing", goldens.add_missing,
                "update: add goldens (first, middle, last frame) for every built-in scene that "
                "has none, leaving the others untouched");
    g->add_option("--scene", goldens.scenes, "only the goldens of this scene (repeatable)");

    DiffCommand diff;
    CLI::App* d = app.add_subcommand(
        "diff", "compare two PNG images by decoded pixels (exit 0 match, 1 differ)");
    d->add_option("a", diff.a, "first image")->required();
    d->add_option("b", diff.b, "second image")->required();
    d->add_option("-o,--output", diff.output,
                  "write a diff image (red: different, yellow: anti-aliasing)");
    d->add_option("--tolerance", diff.options.tolerance, "per-channel difference ignored (0..255)")
        ->check(CLI::Range(0, 255));
    d->add_option("--threshold", diff.options.perceptual_threshold,
                  "YIQ perceptual threshold (0..1)")
        ->check(CLI::Range(0.0, 1.0));
    d->add_option("--max-different", diff.options.max_different, "pixels allowed to differ");
    d->add_flag("!--no-aa", diff.options.detect_antialiasing,
                "count anti-aliased pixels as different");

    StudyCommand study;
    CLI::App* st = app.add_subcommand(
        "study",
        "work-precision study of every integrator, and the stability map (report + plots)");
    st->add_flag("--quick", study.quick, "small grid, under a minute on 2 cores (what CI runs)");
    st->add_option("-o,--output", study.output, "output folder (default: study)");
    st->add_option("--threads", study.threads, "worker threads (default: one per hardware thread)")
        ->check(CLI::PositiveNumber);
    st->add_flag("-q,--quiet", study.quiet, "no progress and no summary");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& h) {
        return app.exit(h);
    } catch (const CLI::ParseError& err) {
        app.exit(err);
        return kBadInput;
    }
    tumble::render::quiet_video_logs();
    if (version) return run_version();
    if (r->parsed()) return run_render(render);
    if (b->parsed()) return run_bench_render(bench);
    if (s->parsed()) return run_simulate(simulate);
    if (e->parsed()) return run_explain(explain);
    if (app.got_subcommand("scenes")) return run_list_scenes();
    if (g->parsed()) return run_goldens(goldens);
    if (d->parsed()) return run_diff(diff);
    if (st->parsed()) return run_study(study);
    std::fputs(app.help().c_str(), stdout);
    return kOk;
}
