// implicit_gyro: semi-implicit Euler with the gyroscopic term taken implicitly (backward Euler) in
// the body frame and solved by one Newton step, as in Catto's GDC 2015 "Numerical Methods" talk and
// Box3D's solver (its residual: I (w2 - w1) + h w2 x I w2 = 0):
//
//   v' = v + h sum F / m
//   w1 = w + h I_w^-1 sum tau                                 (explicit torque kick)
//   a  = R^T w1   (body frame);   f(b) = I (b - a) + h b x I b   (backward Euler on the gyro term)
//   J  = df/db at a = I + h ([a]x I - [I a]x)
//   w' = R (a - J^-1 f(a)) = R (a - J^-1 h (a x I a))           (one Newton step from a)
//   x' = x + h v',   q' = exp(h w') (x) q
//
// Order: 1.
// Conserves: nothing exactly. Exact backward Euler would shrink both |L| and the energy
// (m2 - m1 = -h b x m2 gives |m2|^2 = m1 . m2); the one Newton step keeps it for the energy
// below a bound on h |w|. Torque-free, with d = b - a the Newton step (J d = -h a x I a), dotting
// J d with a and with d gives a . I d = h d . (a x I a) and d . I d + h d . (a x I d) = -h d . (a x
// I a), hence
//   2 E' - 2 E = 2 d . I a + d . I d = -d . I d - 2 h a . (I d x d)
// (the drift q' = exp(h w') q leaves the body-frame w unchanged). |I d x d| <= (I_max - I_min)/2
// |d|^2 and d . I d >= I_min |d|^2, so the energy never increases while
//   h |w| <= I_min / (I_max - I_min).
// Beyond that bound a single Newton step is not backward Euler and may add energy; exact backward
// Euler never would (b . I b = b . I a <= |b|_I |a|_I).
// Known failure: it damps tumbling: energy drains at a rate growing like (h |w|)^2 per step
// (MuJoCo's figure for its analogous scheme, references.md section 2.1; Coumans, Bullet #346:
// "the implicit integrator dampens the coriolis/gyroscopic effect").
#include "physics/compensated.h"
#include "physics/forces.h"
#include "physics/model.h"
#include "physics/rigid_body.h"
#include "physics/state.h"

#include <Eigen/LU>

namespace tumble::physics {

void integrate_implicit_gyro(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies) {
        const Quat q = s.q[i];
        if (loads) {
            s.v[i] += h * m.inv_mass[i] * net_force(m, i);
            s.w[i] += angular_velocity_change(m, i, q, h * net_torque(m, i));
        }
        if (anisotropic(m, i)) {
            const Vec3& I = m.inertia[i];
            const Vec3 a = q.conjugate() * s.w[i];
            const Vec3 Ia = I.cwiseProduct(a);
            const Mat3 J = Mat3(I.asDiagonal()) + h * (skew(a) * I.asDiagonal() - skew(Ia));
            s.w[i] = q * (a - J.inverse() * (h * a.cross(Ia)));
        }
        add_compensated(s.x[i], s.x_carry[i], h * s.v[i]);
        s.q[i] = (quat_exp(h * s.w[i]) * q).normalized();
    }
}

} // namespace tumble::physics
