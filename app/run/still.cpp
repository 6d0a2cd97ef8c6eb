#include "app/run/still.h"
#include "app/run/auto_camera.h"

#include "app/run/frame_source.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene_error.h"

namespace tumble::app {

render::Image render_still(const Scene& given, std::int64_t frame, render::Renderer& renderer) {
    Scene scene = given;
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    frame_automatically(scene, tl); // the still of frame k is frame k of the video
    if (frame < 0 || frame >= tl.frames)
        throw SceneError(scene.source, "frame " + std::to_string(frame),
                         "expected a frame index in [0, " + std::to_string(tl.frames - 1) + "]");
    Simulation sim = make_simulation(scene, tl.h);
    FrameSource source(scene, tl, sim, frame, frame);
    render::SceneView view;
    source.next(view);
    render::Image image;
    renderer.draw(view, image);
    return image;
}

} // namespace tumble::app
