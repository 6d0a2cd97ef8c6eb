#pragma once
// One rendering run, shared by `tumble render` and `tumble bench-render`: the scene's picture
// settings with the command line's overrides, and the frame pipeline (app/pipeline.h) from the
// simulation to a sink.
#include "app/commands.h"
#include "app/pipeline.h"
#include "app/scene.h"
#include "app/simulation.h"
#include "app/timeline.h"
#include "render/frame_sink.h"
#include "render/renderer.h"

#include <cstdint>

namespace tumble::app {

// --width/--height/--fps and the picture switches (--preview, --[no-]shadows, --[no-]aa,
// --[no-]overlay, --[no-]axes) applied to the scene's render settings. Throws SceneError.
void apply_render_overrides(const RenderCommand& cmd, Scene& scene);

// The encoder preset of a run: --preset if given, else "ultrafast" for --preview (a quick look:
// measured, veryfast encoding made the 640x360 preview 1.58x slower than drawing alone, ultrafast
// keeps it near the renderer's pace) and "veryfast" otherwise.
std::string video_preset(const RenderCommand& cmd);

// Throws SceneError when --frame names a frame outside the video.
void check_frame_index(const RenderCommand& cmd, const Timeline& tl);

// --output, or "<scene file stem><suffix>.mp4" ("tumble" for a scene without a file).
std::string output_name(const RenderCommand& cmd, const Scene& scene,
                        const std::string& suffix = "");

// Why `output` cannot take this run ("" when it can): --frame writes one still, a .png.
std::string output_problem(const RenderCommand& cmd, const std::string& output);

// The sink for `output` at the scene's size and frame rate with the command's quality settings,
// creating the output's folder first (not for a name with a %d pattern). Throws render::SinkError.
std::unique_ptr<render::FrameSink> open_render_sink(const RenderCommand& cmd, const Scene& scene,
                                                    const std::string& output);

// The renderer's options for a scene's render settings.
render::RenderOptions render_options(const RenderSettings& settings);

struct RunResult {
    std::int64_t frames = 0;
    bool interrupted = false;
    PipelineStats stats;
};

// Draws frames first..last of `sim` (at t = 0) into `sink` through the pipeline; stops early,
// finishing the frames in flight, on Ctrl-C. Does not finish() the sink. Throws what the stages
// throw (DivergenceError, RenderError, SinkError).
RunResult render_frames(const Scene& scene, const Timeline& tl, Simulation& sim,
                        render::FrameSink& sink, std::int64_t first, std::int64_t last, bool quiet);

// Process-wide malloc settings that spare llvmpipe a page fault storm every frame (see the .cpp).
// render_frames() calls it; other long rendering loops may too.
void tune_allocator_for_rendering();

// A stage table for --stats and benchmarks, one line per stage.
std::string describe_stats(const PipelineStats& stats);

} // namespace tumble::app
