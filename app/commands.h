#pragma once
// The `tumble` subcommands. Each returns the process exit code:
//   0 success, 1 run-time failure (divergence, I/O), 2 bad input (scene, options, output name),
//   128 + signal when interrupted (the outputs are finished first, so a video still plays).
#include "render/image_compare.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tumble::app {

enum ExitCode { kOk = 0, kRunFailed = 1, kBadInput = 2 };

// Options shared by every command that runs a scene.
struct SceneOptions {
    std::string scene; // file or built-in name; empty: the built-in default
    std::optional<std::string> integrator;
    std::optional<double> duration;
    std::optional<double> dt;
    bool quiet = false;
};

struct RenderCommand {
    SceneOptions common;
    std::string output; // empty: "<scene name>.mp4"
    std::optional<int> width, height, fps;
    std::optional<std::int64_t> frame; // render only this frame (to a still .png)
    int crf = 18;
    std::string preset = "veryfast";
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
};

struct DiffCommand {
    std::string a, b;
    std::string output; // diff image, optional
    render::CompareOptions options;
};

int run_render(const RenderCommand& cmd);
int run_goldens(const GoldensCommand& cmd);
int run_diff(const DiffCommand& cmd);
int run_simulate(const SimulateCommand& cmd);
int run_explain(const SceneOptions& opts);
int run_list_scenes();
int run_version();

} // namespace tumble::app
