#pragma once
// Closed-form motions under constant loads, as oracles for tests and `tumble study`.
//   Projectile:  F = m a with a constant:  x(t) = x0 + v0 t + 1/2 a t^2,  v(t) = v0 + a t.
//   Constant torque on a sphere (I_w = I 1, so w x I w = 0): tau = I dw/dt, w(t) = w0 + tau t / I.
//     While w0 and tau are parallel every w(t) is too, the rotations commute and
//     q(t) = exp(w0 t + tau t^2 / (2 I)) (x) q0. For w0 not parallel to tau the orientation has no
//     elementary closed form (a linearly swept axis: parabolic cylinder functions), so the
//     constructor refuses it.
#include "physics/exact/free_rigid_body.h"

namespace tumble::exact {

struct Projectile {
    Vec3 x0, v0, a; // m, m/s, m/s^2

    Vec3 x_at(double t) const { return x0 + t * v0 + (0.5 * t * t) * a; }
    Vec3 v_at(double t) const { return v0 + t * a; }
};

class ConstantTorqueSphere {
  public:
    // inertia: the sphere's moment I > 0; tau: constant world torque. Throws std::domain_error when
    // w0 and tau are not parallel (|w0 x tau| > 1e-12 |w0| |tau|).
    ConstantTorqueSphere(double inertia, const Quat& q0, const Vec3& w0, const Vec3& tau);

    RotationState state_at(double t) const;

  private:
    double inertia_;
    Quat q0_;
    Vec3 w0_, tau_;
};

} // namespace tumble::exact
