#include "app/still.h"

#include "app/scene_error.h"
#include "app/simulation.h"
#include "app/timeline.h"
#include "app/view_builder.h"
#include "physics/step.h"

namespace tumble::app {

render::Image render_still(const Scene& scene, std::int64_t frame, render::Renderer& renderer) {
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    if (frame < 0 || frame >= tl.frames)
        throw SceneError(scene.source, "frame " + std::to_string(frame),
                         "expected a frame index in [0, " + std::to_string(tl.frames - 1) + "]");
    Simulation sim = make_simulation(scene, tl.h);
    for (std::int64_t s = 0; s < frame * tl.steps_per_frame; ++s)
        physics::step(sim.model, sim.state);
    render::SceneView view;
    build_view(scene, sim.model, sim.state, view);
    render::Image image;
    renderer.draw(view, image);
    return image;
}

} // namespace tumble::app
