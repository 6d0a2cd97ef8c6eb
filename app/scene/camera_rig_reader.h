#pragma once
// Reading render.camera (docs/scene-format.md) into a CameraRig (camera_rig.h). Apart from the
// rig itself, so that what includes the scene does not parse the JSON library.
#include "app/scene/camera_rig.h"
#include "app/scene/json_reader.h"

namespace tumble::app {

// Reads render.camera into `rig` (whose base holds the defaults). Throws SceneError.
void read_camera_rig(JsonReader r, CameraRig& rig);

} // namespace tumble::app
