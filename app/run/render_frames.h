#pragma once
// One rendering run, shared by `tumble render` and the render benchmark (bench/render): frames from
// the simulation through the pipeline (app/run/pipeline.h) into a sink, and its stage table.
#include "app/run/pipeline.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "render/frame_sink.h"
#include "render/renderer.h"

#include <cstdint>
#include <span>

namespace tumble::app {

// The renderer's options for a scene's render settings.
render::RenderOptions render_options(const RenderSettings& settings);

struct RunResult {
    std::int64_t frames = 0;
    bool interrupted = false;
    PipelineStats stats;
};

// A state to continue from instead of stepping from t = 0: frame `frame`'s (a checkpoint).
struct ResumePoint {
    std::int64_t frame = 0;
    physics::State state;
};

// Draws frames first..last of `sim` (at t = 0) into `sink` through the pipeline; stops early,
// finishing the frames in flight, on Ctrl-C. Does not finish() the sink. Throws what the stages
// throw (DivergenceError, RenderError, SinkError). With `resume` (frame <= first), the physics
// continues from its state (FrameSource::resume) instead of from t = 0.
RunResult render_frames(const Scene& scene, const Timeline& tl, Simulation& sim,
                        render::FrameSink& sink, std::int64_t first, std::int64_t last, bool quiet,
                        const ResumePoint* resume = nullptr);

// The same for some frames only: `frames` sorted and distinct, each in [0, tl.frames). Each is
// drawn once; the steps between are taken without drawing (FrameSource::skip_to), so frame k is
// the picture `tumble render --frame k` draws. The Python module's render(frames=[...]).
RunResult render_frames(const Scene& scene, const Timeline& tl, Simulation& sim,
                        render::FrameSink& sink, std::span<const std::int64_t> frames, bool quiet);

// Process-wide malloc settings that spare llvmpipe a page fault storm every frame (see the .cpp).
// render_frames() calls it; other long rendering loops may too.
void tune_allocator_for_rendering();

// A stage table for --stats and benchmarks, one line per stage.
std::string describe_stats(const PipelineStats& stats);

} // namespace tumble::app
