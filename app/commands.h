#pragma once
// The `tumble` subcommands. Each returns the process exit code:
//   0 success, 1 run-time failure (divergence, I/O), 2 bad input (scene, options, output name),
//   128 + signal when interrupted (the outputs are finished first, so a video still plays).
#include "render/image_compare.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tumble::app {

enum ExitCode { kOk = 0, kRunFailed = 1, kBadInput = 2 };

// Options shared by every command that runs a scene.
struct SceneOptions {
    std::string scene; // file or built-in name; empty: the built-in default
    std::optional<std::string> integrator;
    std::optional<double> duration;
    std::optional<double> dt;
    int threads = 1; // physics threads for the contact stage (same states for any count)
    bool quiet = false;
};

struct RenderCommand {
    SceneOptions common;
    std::string output; // empty: "<scene name>.mp4"
    std::optional<int> width, height, fps;
    std::optional<std::int64_t> frame; // render only this frame (to a still .png)
    int crf = 18;
    // Encoder preset; unset: "veryfast", or "ultrafast" with --preview (video_preset()).
    std::optional<std::string> preset;
    // Picture switches; unset ones keep the scene's render settings.
    bool preview = false; // 640x360 (unless --width/--height), no shadows, no anti-aliasing
    std::optional<bool> shadows, antialiasing, overlay, axes, vectors;
    bool stats = false; // print each pipeline stage's rate
    // Integrators drawn side by side, each stepping its own copy of the scene (compare_run.cpp).
    std::vector<std::string> compare;
};

// `tumble bench-render`: frames per second per stage and end to end, medians of repeated runs,
// against a null sink measured in the same run (app/bench_command.cpp).
struct BenchRenderCommand {
    std::vector<std::string> cases; // names from the built-in list; empty: all
    int repeats = 3;
    std::string csv;     // append the table here
    std::string machine; // label for the CSV (default: the host name)
    bool quick = false;  // fewer frames per case
};

struct SimulateCommand {
    SceneOptions common;
    std::string output; // states CSV; diagnostics go beside it as <stem>.diagnostics.csv
    int every = 1;      // write every N-th step
};

struct GoldensCommand {
    std::string action; // "check" or "update"
    std::string manifest;
    std::string artifacts = "golden-artifacts"; // where check writes actual and diff images
    bool force = false;
    bool add_missing = false;        // update: only add goldens for built-in scenes without any
    std::vector<std::string> scenes; // only the entries of these scenes (empty: all)
};

struct DiffCommand {
    std::string a, b;
    std::string output; // diff image, optional
    render::CompareOptions options;
};

// `tumble study`: the work-precision study and the stability map (app/study.h, docs/study.md).
struct StudyCommand {
    bool quick = false;           // the small grid CI runs (under a minute on 2 cores)
    std::string output = "study"; // folder for study.csv, study.json, report.md and plots/
    int threads = 0;              // 0: one per hardware thread
    bool quiet = false;
};

int run_render(const RenderCommand& cmd);
int run_compare(const RenderCommand& cmd); // run_render() with --compare
int run_bench_render(const BenchRenderCommand& cmd);
int run_goldens(const GoldensCommand& cmd);
int run_diff(const DiffCommand& cmd);
int run_simulate(const SimulateCommand& cmd);
int run_explain(const SceneOptions& opts);
int run_list_scenes();
int run_version();
int run_study(const StudyCommand& cmd);

} // namespace tumble::app
