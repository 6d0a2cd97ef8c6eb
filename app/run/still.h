#pragma once
// One frame of a scene, rendered in-process: steps the scene to t = k / fps and draws it. Used by
// golden-image checks and anything else that needs a picture without a sink.
#include "app/scene/scene.h"
#include "render/image.h"
#include "render/renderer.h"

#include <cstdint>

namespace tumble::app {

// Renders frame `frame` of `scene` with `renderer` (whose size wins over the scene's). Throws
// SceneError for a frame outside the scene's duration, DivergenceError if the physics diverges.
render::Image render_still(const Scene& scene, std::int64_t frame, render::Renderer& renderer);

} // namespace tumble::app
