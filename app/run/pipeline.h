#pragma once
// The frame pipeline: three stages on three threads, joined by bounded queues, so that
//   physics (step the state, build the SceneView)  ->  render (GL)  ->  output (encode, write)
// run at the same time and the end-to-end rate is set by the slowest stage alone.
//
// Each stage handles frames strictly in order and on one thread, so the frames (and the bytes
// of the output) are exactly those of a sequential loop: determinism is unchanged. The queues
// hold at most `depth` frames in flight; their SceneViews and Images are recycled through return
// queues, so a warmed-up pipeline allocates nothing per frame.
//
// The renderer is created, used and destroyed on the render thread (a GL context is current on
// one thread at a time). An exception in any stage stops the others and is rethrown by run()
// once every thread has joined; frames already produced when the producer stops normally (no
// more frames, or Ctrl-C) are still drawn and written.
#include "render/image.h"
#include "render/renderer.h"
#include "render/scene_view.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace tumble::app {

struct StageStats {
    std::int64_t frames = 0;
    double busy = 0.0; // s spent working (not waiting on a queue)
    double rate() const { return busy > 0.0 ? double(frames) / busy : 0.0; } // frames/s
};

struct PipelineStats {
    StageStats physics, render, output;
    double wall = 0.0; // s, first frame requested to last frame written
    double cpu = 0.0;  // s of CPU time of the whole process (all threads, llvmpipe's too)
    std::int64_t frames = 0;
    double rate() const { return wall > 0.0 ? double(frames) / wall : 0.0; }
};

struct PipelineStages {
    // Fills the next frame's view; returns false when there are no more frames. Physics thread.
    std::function<bool(render::SceneView&)> produce;
    // Makes the renderer, on the render thread, before the first frame.
    std::function<std::unique_ptr<render::Renderer>()> make_renderer;
    // Takes a finished frame, in order. Calling thread.
    std::function<void(const render::Image&)> consume;
};

// Runs until `produce` returns false and every frame it produced has been consumed.
PipelineStats run_pipeline(const PipelineStages& stages, int depth = 3);

} // namespace tumble::app
