// rk4: the classic fourth-order Runge-Kutta method on y = (x, v, q, w), world frame.
//
//   f(y) = (v, sum F / m, 1/2 (0, w) (x) q, I_w^-1 (sum tau - w x I_w w))
//   k1 = f(y), k2 = f(y + h/2 k1), k3 = f(y + h/2 k2), k4 = f(y + h k3)
//   y' = y + h/6 (k1 + 2 k2 + 2 k3 + k4),  then q' <- q' / |q'|
//
// Order: 4 on the translation (exact to round-off for constant force: x(t) is a quadratic). On the
// rotation the stages add quaternion increments in R^4 and the result is projected back onto the
// unit sphere; Buss (2000) warns such "naive" Runge-Kutta on sphere-valued functions can lose
// order, so the order is measured, not assumed: 3.89 and 3.94 on the intermediate-axis flip
// (h = 1/60, 1/120, 1/240 s; tests/physics/integrator_order_test.cpp). It is fourth order: the
// stage derivative 1/2 (0, w) (x) q is linear in q, so the stages solve a smooth ODE in R^4 whose
// exact solution stays on the sphere, and the final projection moves an O(h^5)-accurate point by
// O(h^5). Buss's loss of order concerns schemes whose stages leave that ODE.
// Conserves: nothing exactly. Energy and world angular momentum drift as O(h^4) per unit time.
// Known failure: explicit, so for h |w| beyond about 2.8 (the RK4 stability boundary on the
// imaginary axis) the rotation blows up; the divergence check then stops the run.
#include "physics/compensated.h"
#include "physics/forces.h"
#include "physics/model.h"
#include "physics/rigid_body.h"
#include "physics/state.h"

namespace tumble::physics {
namespace {

struct Rates {
    Vec3 dx, dv;
    Quat dq;
    Vec3 dw;
};

Quat add_scaled(const Quat& q, double s, const Quat& dq) {
    return Quat(q.coeffs() + s * dq.coeffs());
}

Rates rates(const Model& m, int i, const Vec3& v, const Quat& q, const Vec3& w, const Vec3& accel,
            const Vec3& tau) {
    // Stage quaternions leave the unit sphere, so R is taken from q/|q|; an isotropic body's
    // angular acceleration needs no R (rigid_body.h), and no square root is spent on it.
    const Quat unit = anisotropic(m, i) ? q.normalized() : q;
    return {v, accel, quat_derivative(w, q), angular_acceleration(m, i, unit, w, tau)};
}

} // namespace

void integrate_rk4(const Model& m, State& s, double h, std::span<const int> bodies) {
    for (int i : bodies) {
        const Vec3 accel = m.inv_mass[i] * net_force(m, i); // F = m a, constant over the step
        const Vec3 tau = net_torque(m, i);
        const Vec3 v = s.v[i], w = s.w[i];
        const Quat q = s.q[i];

        const Rates k1 = rates(m, i, v, q, w, accel, tau);
        const Rates k2 = rates(m, i, v + 0.5 * h * k1.dv, add_scaled(q, 0.5 * h, k1.dq),
                               w + 0.5 * h * k1.dw, accel, tau);
        const Rates k3 = rates(m, i, v + 0.5 * h * k2.dv, add_scaled(q, 0.5 * h, k2.dq),
                               w + 0.5 * h * k2.dw, accel, tau);
        const Rates k4 =
            rates(m, i, v + h * k3.dv, add_scaled(q, h, k3.dq), w + h * k3.dw, accel, tau);

        const double c = h / 6.0;
        add_compensated(s.x[i], s.x_carry[i], c * (k1.dx + 2.0 * k2.dx + 2.0 * k3.dx + k4.dx));
        s.v[i] = v + c * (k1.dv + 2.0 * k2.dv + 2.0 * k3.dv + k4.dv);
        s.w[i] = w + c * (k1.dw + 2.0 * k2.dw + 2.0 * k3.dw + k4.dw);
        const Quat dq(k1.dq.coeffs() + 2.0 * k2.dq.coeffs() + 2.0 * k3.dq.coeffs() +
                      k4.dq.coeffs());
        s.q[i] = add_scaled(q, c, dq).normalized();
    }
}

} // namespace tumble::physics
