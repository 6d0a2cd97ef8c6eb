// symplectic_euler: semi-implicit Euler, velocities first, then positions with the new velocities;
// the orientation by the exact exponential map of w' h (Jolt, MuJoCo); explicit gyroscopic torque:
//
//   v' = v + h sum F / m
//   w' = w + h I_w^-1 (sum tau - w x I_w w),   I_w = R I_body R^T  (at the old R, w)
//   x' = x + h v'
//   q' = exp(h w') (x) q
//
// The name is the one Box2D, Jolt and Catto's talks use for this scheme, and it holds for the
// translation: for a separable H = T(p) + V(q) (a particle in a potential) the kick-then-drift map
// is symplectic, and its energy error stays bounded over exponentially long times. Rotation is not
// separable (T = 1/2 L . I_w^-1 L depends on the orientation) and the gyroscopic term is taken
// explicitly, so for a tumbling body the map is not symplectic and the energy drifts (below):
// docs/lessons/02-explicit-euler.md says so, and why the name stays.
//
// Order: 1, translation included (under a constant force x' runs h^2 a / 2 ahead per step).
// Conserves: an isotropic torque-free body exactly (w' = w, and q' is the exact rotation). For
// anything that tumbles, nothing. Without torque the rotation exp(h w') leaves w' fixed, so in the
// body frame the step is exactly w_b' = w_b + h I^-1 g, g = m x w_b, m = I w_b, and
//   2 E' = 2 E + h^2 g . I^-1 g  >  2 E   (g is orthogonal to w_b):
// the energy rises every step a body tumbles.
// Known failure: energy and |L| grow on tumbling bodies; the term is quadratic in w, so a fast spin
// runs away ("angular velocities blowing up", Avian #420; Bullet #357 advises the implicit form).
// MuJoCo's Euler, the same scheme, gains 9 % energy in 5 s on its test box (references.md 2.1).
#include "physics/compensated.h"
#include "physics/forces.h"
#include "physics/model.h"
#include "physics/rigid_body.h"
#include "physics/state.h"

namespace tumble::physics {

void integrate_symplectic_euler(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies) {
        if (loads) s.v[i] += h * m.inv_mass[i] * net_force(m, i);
        if (loads || anisotropic(m, i))
            s.w[i] += h * angular_acceleration(m, i, s.q[i], s.w[i], net_torque(m, i));
        add_compensated(s.x[i], s.x_carry[i], h * s.v[i]);
        s.q[i] = (quat_exp(h * s.w[i]) * s.q[i]).normalized();
    }
}

} // namespace tumble::physics
