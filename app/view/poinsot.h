#pragma once
// Poinsot's construction (--poinsot BODY; Poinsot 1834, Goldstein "Classical Mechanics" 5.6) for
// a torque-free body, drawn about its centre of mass in "w space" (one metre on screen per
// `scale` rad/s):
//   - the energy ellipsoid, fixed in the body: the w with w . I_body w = 2T, semi-axes
//     sqrt(2T / I_i) along the principal axes; drawn as a translucent shaded surface with its
//     three principal sections (which turn with the body);
//   - the invariable plane, fixed in space: perpendicular to L at distance 2T / |L| from the
//     centre. Without torque both T and L are constant, so the plane never moves;
//   - they touch at w itself: w . I w = 2T puts w on the ellipsoid, and w . L / |L| =
//     w . I w / |L| = 2T / |L| puts it on the plane; the ellipsoid's normal there, I w = L, is the
//     plane's, so it touches without cutting. As w is the instantaneous axis, the contact point
//     is at rest: the ellipsoid rolls on the plane without slipping;
//   - the polhode, the path of w on the ellipsoid (body frame), and the herpolhode, its path on
//     the plane, named in the frame by a legend. Near the middle axis the polhodes around it
//     cross (the separatrix): a body spun about its middle axis wanders off it and back, the
//     intermediate-axis flip.
// Under a torque about the centre of mass (an applied torque, a contact) T and L change and
// none of this holds: poinsot_torque() says why, the commands warn, and the legend says so.
#include "app/scene/scene.h"
#include "app/view/overlay_layout.h"
#include "physics/model.h"
#include "physics/state.h"
#include "render/scene_view.h"

#include <string>
#include <vector>

namespace tumble::app {

struct PoinsotGeometry {
    physics::Vec3 semi_axes; // of the energy ellipsoid, rad/s, along the principal axes
    physics::Vec3 normal;    // unit L: the invariable plane's normal
    double distance = 0.0;   // 2T / |L|, rad/s: the plane's distance from the centre
    physics::Vec3 contact;   // = w, world: where the ellipsoid touches the plane
};

// From the principal moments, the mass frame's orientation (body -> world) and world w.
PoinsotGeometry poinsot_geometry(const physics::Vec3& inertia, const physics::Quat& q,
                                 const physics::Vec3& w);

// Why `body` may feel a torque about its centre of mass in `model` (a constant applied torque;
// contacts, which push at the surface), for a warning; "" when it moves torque-free (gravity
// alone pulls at the centre of mass and turns nothing).
std::string poinsot_torque(const Scene& scene, const physics::Model& model, int body);
// The warning for the scene's render.poinsot body, when poinsot_torque() finds a reason; "" when
// there is no construction or it holds.
std::string poinsot_warning(const Scene& scene);

// What a camera that frames the construction needs (app/run/auto_camera.h): points that must be
// in frame, and the view: looking down on the invariable plane from the ellipsoid's side, 35
// degrees above it, with the plane level on screen (up: from the plane towards the centre) and
// from the side that `hint` (towards the scene's camera) points to.
struct PoinsotFraming {
    std::vector<glm::dvec3> points;
    glm::dvec3 direction{0.0}, up{0.0}; // from the target towards the camera; up on screen
};
PoinsotFraming poinsot_framing(const physics::Model& model, const physics::State& state, int body,
                               const glm::dvec3& hint);

class PoinsotConstruction {
  public:
    // Fixes the scale so that the ellipsoid's longest semi-axis is 1.5 body sizes at t = 0;
    // records the first sample.
    PoinsotConstruction(const Scene& scene, const physics::Model& model,
                        const physics::State& initial, int body);
    void record(const physics::Model& model, const physics::State& state);
    // The ellipsoid and the plane (translucent surfaces, the ellipsoid's principal sections and
    // the plane's grid), the polhode, the herpolhode and w, for the state now.
    void add(const physics::Model& model, const physics::State& state,
             render::SceneView& view) const;
    // What the colours are, for the frame's legend; shorter names when `compact`. Under a torque
    // the last line says so.
    std::vector<LegendItem> legend(bool compact) const;
    double scale() const { return scale_; } // m per rad/s
    const std::string& torque() const { return torque_; }

  private:
    int body_;
    double scale_ = 1.0;
    std::string torque_;                          // poinsot_torque()
    std::vector<physics::Vec3> w_body_, w_world_; // every frame so far
};

} // namespace tumble::app
