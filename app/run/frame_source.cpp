#include "app/run/frame_source.h"

#include "app/run/prepare_run.h"
#include "app/view/view_builder.h"
#include "io/interrupt.h"
#include "physics/step.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tumble::app {

FrameSource::FrameSource(const Scene& scene, const Timeline& timeline, Simulation& sim,
                         std::int64_t first, std::int64_t last,
                         std::shared_ptr<ChartScale> chart_scale, int canvas_width,
                         int canvas_height)
    : scene_(scene), timeline_(timeline), sim_(sim), first_(first), last_(last),
      done_(first > last), initial_(physics::diagnose(sim.model, sim.state)),
      arrows_(sim.model, sim.state),
      canvas_width_(canvas_width > 0 ? canvas_width : scene.render.width),
      canvas_height_(canvas_height > 0 ? canvas_height : scene.render.height) {
    const RenderSettings& rs = scene.render;
    if (rs.overlay_body.index >= 0)
        overlay_initial_ = physics::diagnose_body(sim.model, sim.state, rs.overlay_body.index);
    if (!rs.chart.empty()) {
        ChartSettings c{rs.chart, rs.chart_body.index, rs.chart_body.name, rs.chart_window};
        chart_ = std::make_unique<ChartHistory>(c, sim.model, sim.state);
        chart_scale_ =
            chart_scale ? std::move(chart_scale) : std::make_shared<ChartScale>(rs.chart.size());
        chart_scale_->include(*chart_, 0);
    }
    if (rs.trails) {
        const auto frames = std::size_t(std::ceil(rs.trail_seconds * timeline.fps)) + 1;
        trails_ = std::make_unique<Trails>(scene, sim.model, sim.state, frames, rs.trail_axis);
    }
    if (rs.poinsot.index >= 0)
        poinsot_ =
            std::make_unique<PoinsotConstruction>(scene, sim.model, sim.state, rs.poinsot.index);
    lay_out();
}

OverlayInfo FrameSource::overlay_info() const {
    const int body = scene_.render.overlay_body.index;
    OverlayInfo info;
    info.t = sim_.state.time(sim_.model);
    info.step = sim_.state.step;
    info.integrator = physics::integrator_info(sim_.model.integrator).name;
    info.h = sim_.model.dt;
    info.now = body < 0 ? physics::diagnose(sim_.model, sim_.state)
                        : physics::diagnose_body(sim_.model, sim_.state, body);
    info.initial = body < 0 ? initial_ : overlay_initial_;
    if (body >= 0) info.subject = scene_.render.overlay_body.name;
    if (sim_.estimate.estimator) info.estimate = estimate_overlay(*sim_.estimate.estimator, body);
    return info;
}

// What the panels keep clear of: the bodies, arrows and construction on the screen at frames
// spread over the whole run (a pre-pass of the physics from t = 0, as camera.auto's: the same
// for a still, a video or a shard), until the run ends or diverges. Its memory is 48 samples'
// boxes whatever the duration; Ctrl-C stops it within a frame (io::Interrupted).
std::vector<ScreenBox> FrameSource::swept_boxes() const {
    constexpr std::int64_t kSamples = 48;
    Simulation pre = start_run(scene_, timeline_, {1, false}); // the run's own steps, no estimate
    std::vector<ScreenBox> boxes;
    render::SceneView view;
    const std::int64_t frames = timeline_.frames,
                       every = std::max<std::int64_t>(1, frames / kSamples);
    try {
        for (std::int64_t k = 0; k < frames; ++k) {
            io::InterruptGuard::stop_if_requested("the overlay layout's pre-pass");
            if (k > 0)
                for (int s = 0; s < timeline_.steps_per_frame; ++s) pre.step();
            if (k % every != 0 && k != frames - 1) continue;
            build_view(scene_, pre.model, pre.state, view);
            if (scene_.render.vectors) arrows_.add(pre.model, pre.state, view);
            view.glass.clear(), view.lines.clear();
            if (poinsot_) poinsot_->add(pre.model, pre.state, view);
            const std::vector<ScreenBox> now = keep_visible(view, canvas_width_, canvas_height_);
            boxes.insert(boxes.end(), now.begin(), now.end());
        }
    } catch (const physics::DivergenceError&) { // the run itself will say so, frame by frame
    }
    return boxes;
}

void FrameSource::lay_out() {
    OverlayContent content;
    if (scene_.render.overlay) {
        const OverlayInfo info = overlay_info();
        overlay_lines(info, content.text);
        overlay_lines(info, content.compact_text, true);
    }
    for (const bool compact : {false, true}) {
        std::vector<LegendItem>& legend = compact ? content.compact_legend : content.legend;
        if (scene_.render.vectors) legend = VectorArrows::legend(compact);
        if (poinsot_)
            for (LegendItem& item : poinsot_->legend(compact)) legend.push_back(std::move(item));
    }
    content.charts = chart_ ? chart_->panels() : 0;
    if (content.text.empty() && content.legend.empty() && content.charts == 0) return;
    overlays_ = FrameOverlays(swept_boxes(), canvas_width_, canvas_height_, content);
}

void FrameSource::record() {
    if (chart_) {
        chart_->record(sim_.model, sim_.state);
        chart_scale_->include(*chart_, chart_->samples() - 1);
    }
    if (trails_) trails_->record(sim_.model, sim_.state);
    if (poinsot_) poinsot_->record(sim_.model, sim_.state);
}

void FrameSource::resume(std::int64_t frame, const physics::State& state) {
    if (frame < 0 || frame > first_ || k_ != 0 ||
        state.step != frame * std::int64_t{timeline_.steps_per_frame})
        throw std::invalid_argument("cannot resume frame " + std::to_string(frame) + " at step " +
                                    std::to_string(state.step) + " before frame " +
                                    std::to_string(first_));
    sim_.state = state;
    k_ = frame;
}

void FrameSource::skip_to(std::int64_t frame) {
    if (done_ || frame < std::max(k_, first_) || frame > last_)
        throw std::invalid_argument("cannot skip to frame " + std::to_string(frame) +
                                    " from frame " + std::to_string(k_) + " of " +
                                    std::to_string(first_) + ".." + std::to_string(last_));
    while (k_ < frame) step_one_frame();
}

void FrameSource::step_one_frame() {
    for (int s = 0; s < timeline_.steps_per_frame; ++s) sim_.step();
    ++k_;
    record();
}

// The world's additions (trails, the construction) and, once laid out, the panels over them.
void FrameSource::add_teaching(render::SceneView& view) const {
    view.lines.clear();
    view.glass.clear();
    view.canvas.clear();
    if (trails_) trails_->add(view);
    if (poinsot_) poinsot_->add(sim_.model, sim_.state, view);
    overlays_.draw_legend(view.canvas);
    if (chart_)
        draw_charts(*chart_, *chart_scale_, sim_.state.time(sim_.model), scene_.duration,
                    overlays_.font(), overlays_.charts(), view.canvas);
}

bool FrameSource::next(render::SceneView& view) {
    if (done_) return false;
    while (k_ < first_) step_one_frame();
    build_view(scene_, sim_.model, sim_.state, view);
    if (scene_.render.vectors) arrows_.add(sim_.model, sim_.state, view);
    add_teaching(view);
    view.overlay_at = overlays_.text_at();
    if (scene_.render.overlay)
        overlay_lines(overlay_info(), view.overlay, overlays_.compact_text());
    else
        view.overlay.clear();
    if (observer_) observer_(k_, sim_);
    if (k_ >= last_)
        done_ = true;
    else
        step_one_frame();
    return true;
}

} // namespace tumble::app
