#pragma once
// Small contact scenes on the ground (physics/scenes/ground.h), each testing one thing the contact
// stage must get right: bounces, static and sliding friction, resting stacks, momentum passed
// along a row, a fast body against a thin wall. Gravity is the default 9.81 m/s^2 down (-z)
// unless stated; SI units (m, kg, s). Each takes the step dt so that a test runs it at h, 2h, 4h.
#include "physics/scenes/scene.h"

namespace tumble::scenes {

// Radius of the ball_drop() ball, m: an impact oracle needs it (bottom = centre - radius).
inline constexpr double kDropBallRadius = 0.1;

// A ball of radius 0.1 m and 1 kg dropped from rest with its bottom h0 (m) above the ground, with
// Newton's `restitution`: free fall between bounces, apexes e^(2k) h0. Bodies: ground, ball.
Scene ball_drop(double restitution, double h0, double dt);

// A 0.2 x 0.2 x 0.1 m box of 1 kg resting on a plane tilted by `angle` (rad) about y, both with
// friction mu: it stays when tan(angle) <= mu and slides with a = g (sin - mu cos) otherwise.
// Bodies: the tilted plane, box. `sleeping` sets world.contact.sleeping.
Scene incline(double angle, double mu, double dt, bool sleeping);

// n cubes of edge `edge` (m) and 1 kg stacked on the ground, exactly touching, sleeping off: the
// exact motion is none, so every movement is drift (sag, creep, jitter). Bodies: ground, then the
// cubes bottom to top.
Scene box_stack(int n, double edge, double dt);

// A 2D pyramid of 20 cubes of 0.5 m and 1 kg: rows of 6, 5, 4, 3, 2 along x with 1 cm gaps,
// sleeping off; it must stand. Bodies: ground, then the rows bottom to top.
Scene pyramid(double dt);

// Newton's cradle in free space (no gravity): five touching balls of radius 5 cm and 0.2 kg,
// steel-like (restitution 1, no friction), the first sent in along +x at `speed` (m/s) from 10 cm
// away: the last one leaves with it. Bodies: the five balls.
Scene cradle(double speed, double dt);

// A 2 cm ball of 10 g fired along +x at `speed` (m/s) from x = -1 m towards a static wall 1 cm
// thick at x = 0, no gravity: the tunnelling test. Bodies: wall, ball.
Scene bullet(double speed, double dt);

} // namespace tumble::scenes
