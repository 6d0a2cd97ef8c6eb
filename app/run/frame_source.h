#pragma once
// The frames of a scene, in order: steps the simulation to each frame time t_k = k / fps
// (app/run/timeline.h) and describes what to draw (the SceneView: bodies, camera, overlay text).
// Used by `tumble render` (on the pipeline's physics thread) and by stills, so that frame k of a
// still and frame k of a video are the same picture.
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "app/view/frame_overlays.h"
#include "app/view/overlay_text.h"
#include "app/view/poinsot.h"
#include "app/view/strip_chart.h"
#include "app/view/trails.h"
#include "app/view/vector_arrows.h"
#include "physics/diagnostics.h"
#include "render/scene_view.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace tumble::app {

class FrameSource {
  public:
    // Frames first..last (inclusive) of `sim`, which must be at t = 0. Keeps references. The
    // charts' y ranges come from `chart_scale` when given (shared by the tiles of --compare),
    // else from a scale of its own; they are drawn for an image `canvas_width` x
    // `canvas_height` (0: the scene's size).
    FrameSource(const Scene& scene, const Timeline& timeline, Simulation& sim, std::int64_t first,
                std::int64_t last, std::shared_ptr<ChartScale> chart_scale = nullptr,
                int canvas_width = 0, int canvas_height = 0);

    // Continues from `state`, the state of frame `frame` <= first (a checkpoint, app/cluster),
    // instead of stepping there from t = 0. Call before next(). What is measured against t = 0
    // (the overlay's initial energy, the arrows' scales) keeps the values of the simulation's
    // state at construction. Throws std::invalid_argument when `state` is not at that frame's step.
    void resume(std::int64_t frame, const physics::State& state);

    // Fills `view` with the next frame (reusing its storage) and steps on to the one after.
    // Returns false when every frame has been produced. Throws physics::DivergenceError.
    bool next(render::SceneView& view);

    std::int64_t next_frame() const { return k_; }

    // Steps on to frame `frame` (first, next_frame() <= frame <= last) without describing the
    // frames between, so that next() gives frame `frame`: a sparse set of frames (the Python
    // module's render(frames=[0, 60, 120])) costs their pictures only. The teaching overlays still
    // record every frame, so frame k is the same picture as in a whole video. Throws
    // std::invalid_argument for a frame outside that range.
    void skip_to(std::int64_t frame);

    // Called by next() with each frame's index and the simulation at that frame's time, before
    // it steps on: for callers that sample states at frame times (a regression suite's state
    // checks) in the same pass that draws the frames.
    using Observer = std::function<void(std::int64_t frame, const Simulation& sim)>;
    void observe(Observer observer) { observer_ = std::move(observer); }
    const physics::Diagnostics& initial() const { return initial_; }

  private:
    void step_one_frame();
    void record(); // the teaching overlays' sample of this frame
    void add_teaching(render::SceneView& view) const;
    OverlayInfo overlay_info() const; // the overlay's numbers now
    std::vector<ScreenBox> swept_boxes() const;
    void lay_out(); // plans overlays_

    const Scene& scene_;
    const Timeline& timeline_;
    Simulation& sim_;
    std::int64_t k_ = 0, first_, last_;
    bool done_ = false;
    physics::Diagnostics initial_;
    VectorArrows arrows_;                  // drawn when scene.render.vectors
    physics::Diagnostics overlay_initial_; // of render.overlay_body, when given
    // Teaching overlays, when the scene asks for them.
    std::unique_ptr<ChartHistory> chart_;
    std::shared_ptr<ChartScale> chart_scale_;
    std::unique_ptr<Trails> trails_;
    std::unique_ptr<PoinsotConstruction> poinsot_;
    int canvas_width_, canvas_height_;
    FrameOverlays overlays_;
    Observer observer_;
};

} // namespace tumble::app
