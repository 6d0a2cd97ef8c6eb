#pragma once
// camera.auto (docs/scene-format.md, render.camera): one fixed camera, chosen before the first
// frame, that keeps every dynamic body in view for the whole run. A pre-pass steps the scene
// over every frame time (the same steps the render will take) and collects the bodies' bounding
// spheres (swept_spheres.h); the camera then looks at them from the rig's direction, upright
// along the scene's up axis (against gravity), and stands back just far enough that every
// sphere lies inside the frame with the margin. One camera for the
// whole run: steady by construction, no jitter. A scene that gives no camera gets this one.
#include "app/run/timeline.h"
#include "app/scene/scene.h"

namespace tumble::app {

// Where the camera goes for a swept box [lo, hi] seen along `direction` (unit, from the target
// towards the camera) with `up`, vertical field of view `fov_y_deg`, image aspect `aspect`
// (width / height) and `margin` (a fraction of the half-frame left free on every side). Pure
// geometry, for the pre-pass and its tests.
render::Camera frame_box(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& direction,
                         const glm::dvec3& up, double fov_y_deg, double aspect, double margin);

// If scene.render.camera is automatic, runs the pre-pass over the timeline's frames and turns it
// into the fixed camera that keeps every sphere of swept_spheres.h in frame; if it frames
// Poinsot's construction (Mode::Poinsot), into the camera that looks down on the invariable plane
// at t = 0 with the construction in frame (app/view/poinsot.h: poinsot_framing). Memory is bounded
// whatever the duration; a progress bar shows on a terminal unless `quiet`. Throws what stepping
// throws (a divergence names its body and step, as the render itself would) and io::Interrupted on
// Ctrl-C (io/interrupt.h).
void frame_automatically(Scene& scene, const Timeline& tl, bool quiet = true);

} // namespace tumble::app
