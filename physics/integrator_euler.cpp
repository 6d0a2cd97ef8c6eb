// euler: explicit (forward) Euler on (x, v, R, w), the course notes' simulation loop as written:
//
//   x' = x + h v
//   v' = v + h sum F / m
//   R' = R + h [w]x R,  then re-orthonormalised (Gram-Schmidt on the columns, the body axes)
//   w' = w + h I_w^-1 (sum tau - w x I_w w),   I_w = R I_body R^T
//
// Every right-hand side is evaluated at the start of the step.
// Order: 1 (translation too: x lags by h^2 g / 2 per step under gravity).
// Conserves: nothing exactly. R' stays a rotation only because of the re-orthonormalisation.
// Known failure: energy and |L| drift at first order, and in this world-frame form they fall.
// Torque-free, with m = I w_b and g = m x w_b (body frame), the update of w alone would give
// w_b' = w_b + h I^-1 g and 2 E' = 2 E + h^2 g . I^-1 g (a gain: g is orthogonal to w_b; that is
// the explicit Euler of Euler's equations in the body frame, and symplectic_euler). But R turns
// with the old w while w moves, so in the new body frame w_b' = w_b + h I^-1 g - h^2 w_b x I^-1 g,
// and the last term takes away twice the gain:
//   2 E' = 2 E - h^2 g . I^-1 g + O(h^3)   (plus an O(h^2) term of either sign from Gram-Schmidt,
//                                            which turns R by O(h^2) compared with exp(h w) R).
// Measured on MuJoCo's box (h = 0.01, 5 s): E / E0 = 0.847, |L| / |L0| = 0.80; the issue and
// MuJoCo's +9 % describe the semi-implicit scheme (symplectic_euler here, which measures 1.087).
// A teaching baseline, not a method to use.
#include "physics/compensated.h"
#include "physics/forces.h"
#include "physics/model.h"
#include "physics/rigid_body.h"
#include "physics/state.h"

namespace tumble::physics {
namespace {

// The nearest rotation the course notes reach for: normalise the first axis, make the second
// orthogonal to it and normalise, and take the third as their cross product.
Mat3 orthonormalised(const Mat3& a) {
    Mat3 r;
    r.col(0) = a.col(0).normalized();
    r.col(1) = (a.col(1) - r.col(0).dot(a.col(1)) * r.col(0)).normalized();
    r.col(2) = r.col(0).cross(r.col(1));
    return r;
}

// q and -q are the same rotation; keep the sign continuous from step to step.
Quat same_hemisphere(const Quat& q, const Quat& previous) {
    return q.dot(previous) < 0.0 ? Quat(-q.coeffs()) : q;
}

} // namespace

void integrate_euler(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies) {
        const Vec3 v = s.v[i], w = s.w[i];
        const Mat3 R = s.q[i].toRotationMatrix();
        add_compensated(s.x[i], s.x_carry[i], h * v);
        if (loads) s.v[i] += h * m.inv_mass[i] * net_force(m, i);
        if (loads || anisotropic(m, i))
            s.w[i] += h * angular_acceleration(m, i, s.q[i], w, net_torque(m, i));
        const Mat3 R_next = orthonormalised(R + h * skew(w) * R);
        s.q[i] = same_hemisphere(Quat(R_next).normalized(), s.q[i]);
    }
}

} // namespace tumble::physics
