#pragma once
// Viscous rotary dampers: a torque between two bodies proportional to the difference of their
// angular velocities,
//   tau_A = c (w_B - w_A),   tau_B = c (w_A - w_B)     (c in N m s),
// the couple a rotor feels in a cavity of viscous fluid (Kane's spherical nutation damper: Kane,
// Likins and Levinson, *Spacecraft Dynamics*, 1983, section 4.4). The two torques are equal and
// opposite, so the bodies' total angular momentum is untouched, while the kinetic energy falls at
// the rate c |w_B - w_A|^2: a damper is internal dissipation, what turns Explorer 1 end over end
// (docs/lessons/11-dissipation.md). One of the two may be static: the couple then brakes the
// other against the world (tau = -c w).
//
// The damper stage runs after the rest of the step (step.cpp), splitting the couple from the free
// motion (first order in h). Over its step the world inverse inertias are frozen, and the relative
// velocity u = w_B - w_A obeys du/dt = -c K u with K = I_A^-1 + I_B^-1 (symmetric, positive
// definite), solved exactly: u(h) = exp(-c h K) u0 through K's eigenvectors. The impulse moved from
// B to A is P = K^-1 (u0 - u(h)) = V diag((1 - exp(-c h k)) / k) V^T u0, applied as w_A += I_A^-1
// P, w_B -= I_B^-1 P: momentum exactly conserved, energy never gained, at any h.
#include "physics/model.h"
#include "physics/state.h"

namespace tumble::physics {

void apply_dampers(const Model& m, State& s, double h);

} // namespace tumble::physics
