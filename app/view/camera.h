#pragma once
// Where the camera is at a frame's time: the scene's camera rig (app/scene/camera_rig.h) as a pure
// function of t and the followed body's position, so frame k's camera needs no history.
#include "app/scene/camera_rig.h"
#include "render/scene_view.h"

namespace tumble::app {

// The camera at time t. `body` is the followed body's position (ignored by other modes).
render::Camera camera_at(const CameraRig& rig, double t, const glm::dvec3& body);

} // namespace tumble::app
