#pragma once
// Free-flight scenes whose motion the oracles of physics/exact know exactly (torque-free bodies,
// free fall, a torque along the spin), used by the integrator tests, the benchmarks and `tumble
// study`. The scenes need no oracle to be built, so they live here; the oracles stay in
// tumble_exact. SI units (m, kg, s, rad).
#include "physics/scenes/scene.h"

namespace tumble::scenes {

// The default scene's book: a box 0.22 x 0.05 x 0.30 m of 0.8 kg at rest at the origin. Moments
// (6.17e-3, 9.23e-3, 3.39e-3) kg m^2: y is the largest axis, x the middle one, z the smallest.
physics::BodyDef book();

// The book spun at 6 rad/s about its middle axis with a 0.05 rad/s wobble on the other two; no
// gravity. It turns over (the Dzhanibekov flip) at t = 2.07 s and every 3.72 s after; `duration`
// covers the first flip.
Scene intermediate_axis_scene();

// MuJoCo's energy test box: half sizes (0.1, 0.2, 0.3) m, 1 kg, w0 = (1, 2, 3) rad/s, no gravity.
Scene tumbling_box_scene();

// Gravity and spin: the book thrown up while turning about its largest axis, and a ball spun up
// by a constant torque parallel to its spin, both under g = 9.81 m/s^2.
Scene gravity_spin_scene();

// `count` torque-free spheres without gravity, each spinning about a different axis: the case
// where the assembled step skips the gravity, load and gyroscopic work entirely. They start on a
// grid in the plane z = 0 and fly apart (in-plane velocity 0.2/s times the offset from the
// centre, plus a different vertical speed each), so no two ever meet: torque-free for ever, and
// the scene runs no contact stage (physics/can_touch.h).
Scene torque_free_spheres(int count);

} // namespace tumble::scenes
