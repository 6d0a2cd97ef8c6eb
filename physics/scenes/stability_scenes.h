#pragma once
// The scenes of the contact stability map (`tumble study`, docs/study.md): each holds one way a
// contact scene fails when the step is too coarse. Beside contact_scenes.h's stacks and bullet:
// a heavy cube on a light one, a sharp-tipped top spun fast on the table, a ball resting on it.
// Gravity 9.81 m/s^2 down (-z), SI units; each takes the step dt and the contact substeps
// (0: the default, the fewest with h / n <= 1/480 s).
#include "physics/mesh.h"
#include "physics/scenes/scene.h"

#include <memory>

namespace tumble::scenes {

// Two 0.2 m cubes on the ground, sleeping off: the bottom one 1 kg, the top one `ratio` kg (heavy
// on light). Bodies: ground, bottom cube, top cube.
Scene mass_ratio_stack(double ratio, double dt, int substeps);

// A top as a convex solid of revolution about +z with a point tip at the origin: a cone widening
// to a 4 cm rim at z = 3 cm, a 6 mm band, a shallower cone up to a flat crown of 8 mm radius at
// z = 5.6 cm (assets/meshes/top.obj's profile with a sharp tip), `segments` sides.
std::shared_ptr<const physics::TriangleMesh> sharp_top_mesh(int segments = 48);

// That top (density 1200 kg/m^3, friction 1 on a table of friction 1) standing on its tip,
// tilted 15 degrees about x and spun at `spin` rad/s about its own axis, sleeping off. The
// heaviest rotation a table scene asks of the contact stage: a point at the rim moves spin * 4 cm
// per second. Bodies: ground, top.
Scene fast_top(double spin, double dt, int substeps);

// A ball of radius 0.1 m and 1 kg resting on the ground, exactly touching, sleeping off: the
// exact motion is none, and its energy m g r must never grow. Bodies: ground, ball.
Scene resting_ball(double dt, int substeps);

} // namespace tumble::scenes
