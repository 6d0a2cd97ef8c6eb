#pragma once
// Conserved and monitored quantities, computed from a state on demand (not every step unless the
// caller asks): energies, linear momentum and world angular momentum.
//   T_lin = 1/2 m v.v          T_rot = 1/2 w . I_w w
//   V     = - m s g . x         (s: gravity scale; V = m g z for g = (0, 0, -g))
//   P     = sum m v            L = sum (x x m v + I_w w)   (about the world origin)
#include "physics/model.h"
#include "physics/state.h"

namespace tumble::physics {

struct Diagnostics {
    double kinetic_linear = 0.0;          // J
    double kinetic_angular = 0.0;         // J
    double potential = 0.0;               // J, gravitational, zero at the world origin
    Vec3 linear_momentum = Vec3::Zero();  // kg m/s
    Vec3 angular_momentum = Vec3::Zero(); // kg m^2/s, world frame, about the origin

    double kinetic() const { return kinetic_linear + kinetic_angular; }
    double energy() const { return kinetic() + potential; }
};

Diagnostics diagnose(const Model& model, const State& state);

// One body's share: its energies and linear momentum, and its angular momentum about its own
// centre of mass (the spin I_w w, the L of Euler's equations tau = dL/dt = I dw/dt + w x I w),
// not about the origin. Zero for a static body.
Diagnostics diagnose_body(const Model& model, const State& state, int body);

// Spin angular momentum of one body about its centre of mass, I_w w, world frame.
Vec3 spin_angular_momentum(const Model& model, const State& state, int body);

} // namespace tumble::physics
