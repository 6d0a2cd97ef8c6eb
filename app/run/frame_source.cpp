#include "app/run/frame_source.h"

#include "app/view/overlay_text.h"
#include "app/view/view_builder.h"
#include "physics/step.h"

#include <stdexcept>
#include <string>

namespace tumble::app {

FrameSource::FrameSource(const Scene& scene, const Timeline& timeline, Simulation& sim,
                         std::int64_t first, std::int64_t last)
    : scene_(scene), timeline_(timeline), sim_(sim), first_(first), last_(last),
      done_(first > last), initial_(physics::diagnose(sim.model, sim.state)),
      arrows_(sim.model, sim.state) {}

void FrameSource::resume(std::int64_t frame, const physics::State& state) {
    if (frame < 0 || frame > first_ || k_ != 0 ||
        state.step != frame * std::int64_t{timeline_.steps_per_frame})
        throw std::invalid_argument("cannot resume frame " + std::to_string(frame) + " at step " +
                                    std::to_string(state.step) + " before frame " +
                                    std::to_string(first_));
    sim_.state = state;
    k_ = frame;
}

void FrameSource::step_one_frame() {
    for (int s = 0; s < timeline_.steps_per_frame; ++s) sim_.step();
    ++k_;
}

bool FrameSource::next(render::SceneView& view) {
    if (done_) return false;
    while (k_ < first_) step_one_frame();
    build_view(scene_, sim_.model, sim_.state, view);
    if (scene_.render.vectors) arrows_.add(sim_.model, sim_.state, view);
    if (scene_.render.overlay) {
        OverlayInfo info;
        info.t = sim_.state.time(sim_.model);
        info.step = sim_.state.step;
        info.integrator = physics::integrator_info(sim_.model.integrator).name;
        info.h = sim_.model.dt;
        info.now = physics::diagnose(sim_.model, sim_.state);
        info.initial = initial_;
        overlay_lines(info, view.overlay);
        if (scene_.render.vectors) view.overlay.emplace_back(VectorArrows::legend());
    } else {
        view.overlay.clear();
    }
    if (k_ >= last_)
        done_ = true;
    else
        step_one_frame();
    return true;
}

} // namespace tumble::app
