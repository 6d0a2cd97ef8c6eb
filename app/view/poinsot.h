#pragma once
// Poinsot's construction (--poinsot BODY; Poinsot 1834, Goldstein "Classical Mechanics" 5.6) for
// a torque-free body, drawn about its centre of mass in "w space" (one metre on screen per
// `scale` rad/s):
//   - the energy ellipsoid, fixed in the body: the w with w . I_body w = 2T, semi-axes
//     sqrt(2T / I_i) along the principal axes;
//   - the invariable plane, fixed in space: perpendicular to L at distance 2T / |L| from the
//     centre. Without torque both T and L are constant, so the plane never moves;
//   - they touch at w itself: w . I w = 2T puts w on the ellipsoid, and w . L / |L| =
//     w . I w / |L| = 2T / |L| puts it on the plane; the ellipsoid's normal there, I w = L, is the
//     plane's, so it touches without cutting. As w is the instantaneous axis, the contact point
//     is at rest: the ellipsoid rolls on the plane without slipping;
//   - the polhode, the path of w on the ellipsoid (body frame), and the herpolhode, its path on
//     the plane. Near the middle axis the polhodes around it cross (the separatrix): a body spun
//     about its middle axis wanders off it and back, the intermediate-axis flip.
#include "app/scene/scene.h"
#include "physics/model.h"
#include "physics/state.h"
#include "render/scene_view.h"

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

class PoinsotConstruction {
  public:
    // Fixes the scale so that the ellipsoid's longest semi-axis is 1.5 body sizes at t = 0;
    // records the first sample.
    PoinsotConstruction(const physics::Model& model, const physics::State& initial, int body);
    void record(const physics::Model& model, const physics::State& state);
    // The ellipsoid (as meridians and parallels), the plane (a grid), the polhode, the
    // herpolhode and w, for the state now.
    void add(const physics::Model& model, const physics::State& state,
             render::Polylines& lines) const;
    double scale() const { return scale_; } // m per rad/s

  private:
    int body_;
    double scale_ = 1.0;
    std::vector<physics::Vec3> w_body_, w_world_; // every frame so far
};

} // namespace tumble::app
