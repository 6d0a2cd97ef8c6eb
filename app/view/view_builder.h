#pragma once
// Physics state -> what the renderer draws. The only place that knows both sides.
#include "app/scene/scene.h"
#include "physics/model.h"
#include "physics/state.h"
#include "render/scene_view.h"

namespace tumble::app {

// Sets camera, light and background from the scene and refills view.instances (keeping its
// capacity: no allocation per frame once warmed up) from the bodies' current poses.
void build_view(const Scene& scene, const physics::Model& model, const physics::State& state,
                render::SceneView& view);

} // namespace tumble::app
