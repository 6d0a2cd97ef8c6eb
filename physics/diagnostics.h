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

// One body's share of the sums above (zero for a static body); `tumble plot` draws it per body.
struct BodyDiagnostics {
    double kinetic_linear = 0.0;         // 1/2 m v.v, J
    double kinetic_angular = 0.0;        // 1/2 w . I_w w, J
    double potential = 0.0;              // - m s g . x, J
    Vec3 linear_momentum = Vec3::Zero(); // m v
    Vec3 spin = Vec3::Zero();            // I_w w, about the centre of mass, world

    double kinetic() const { return kinetic_linear + kinetic_angular; }
    double energy() const { return kinetic() + potential; }
};
BodyDiagnostics diagnose_body(const Model& model, const State& state, int body);

// Spin angular momentum of one body about its centre of mass, I_w w, world frame.
Vec3 spin_angular_momentum(const Model& model, const State& state, int body);

} // namespace tumble::physics
