#pragma once
// Scenes whose motion the oracles of this folder know exactly, shared by the tests, the benchmarks
// and `tumble study`. Each is a plain WorldDef + BodyDefs (physics/build.h), so a caller builds it
// with its own integrator and step.
#include "physics/build.h"

#include <string>
#include <vector>

namespace tumble::exact {

struct ReferenceScene {
    std::string name;
    physics::WorldDef world;
    std::vector<physics::BodyDef> bodies;
    double duration = 1.0; // s, a horizon over which the scene shows what it is for
};

// The default scene's book (box 0.22 x 0.05 x 0.30 m, 0.8 kg) spun at 6 rad/s about its middle
// axis with a 0.05 rad/s wobble on the other two; no gravity. It turns over (the Dzhanibekov flip)
// at t = 2.07 s and every 3.72 s after; `duration` covers the first flip.
ReferenceScene intermediate_axis_scene();

// MuJoCo's energy test box: half sizes (0.1, 0.2, 0.3) m, 1 kg, w0 = (1, 2, 3) rad/s, no gravity.
ReferenceScene tumbling_box_scene();

// Gravity and spin: the book thrown up while turning about its largest axis, and a ball spun up
// by a constant torque parallel to its spin, both under g = 9.81 m/s^2.
ReferenceScene gravity_spin_scene();

// `count` torque-free spheres without gravity, each spinning about a different axis: the case
// where the assembled step skips the gravity, load and gyroscopic work entirely. They start on a
// grid in the plane z = 0 and fly apart (in-plane velocity 0.2/s times the offset from the
// centre, plus a different vertical speed each), so no two ever meet: torque-free for ever, and
// the scene runs no contact stage (physics/can_touch.h).
ReferenceScene torque_free_spheres(int count);

} // namespace tumble::exact
