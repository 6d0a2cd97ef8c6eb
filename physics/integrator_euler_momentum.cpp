// euler_momentum: explicit Euler on the course notes' alternative state (x, P, q, L), momenta in
// the world frame:
//
//   x' = x + h P / m
//   P' = P + h sum F
//   q' = q + h 1/2 (0, w) (x) q,  then q' / |q'|
//   L' = L + h sum tau
//   w' = I_w'^-1 L',   I_w' = R(q') I_body R(q')^T
//
// The canonical state keeps (v, w), so P = m v and L = I_w w on entry and v = P / m on exit.
// Order: 1.
// Conserves: world angular momentum exactly when there is no torque (L' = L, up to the round-off
// of converting L to w and back each step), linear momentum without force. All the error lands
// in the orientation, and through it in w = I_w^-1 L and the energy 1/2 L . I_w^-1 L.
// Known failure: the first-order orientation error makes the spin axis wander in the body, so the
// energy drifts (either way) at O(h) per unit time although L is exact: the cheapest way to pass
// an "L is conserved" test while being wrong (references.md section 2.2).
#include "physics/compensated.h"
#include "physics/forces.h"
#include "physics/model.h"
#include "physics/rigid_body.h"
#include "physics/state.h"

namespace tumble::physics {

void integrate_euler_momentum(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies) {
        const Quat q = s.q[i];
        add_compensated(s.x[i], s.x_carry[i], h * s.v[i]); // P / m = v
        if (loads) s.v[i] += h * m.inv_mass[i] * net_force(m, i);
        s.q[i] = Quat(q.coeffs() + h * quat_derivative(s.w[i], q).coeffs()).normalized();
        if (!anisotropic(m, i)) {
            // I_w = I 1: L = I w and w' = L' / I, i.e. w' = w + h tau / I.
            if (loads) s.w[i] += h * m.inv_inertia[i].x() * net_torque(m, i);
            continue;
        }
        const Vec3 L = world_inertia_times(q, m.inertia[i], s.w[i]) + h * net_torque(m, i);
        s.w[i] = world_inertia_inverse_times(s.q[i], m.inv_inertia[i], L);
    }
}

} // namespace tumble::physics
