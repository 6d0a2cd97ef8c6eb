#pragma once
// The Newton-Euler equations of one rigid body in the world frame, written the way the course
// notes write them. Every integrator is built from these few functions.
//
//   Newton:       sum F = m dv/dt
//   Euler:        sum tau = I_w dw/dt + w x (I_w w),   I_w = R I_body R^T
//   Kinematics:   dx/dt = v,   dq/dt = 1/2 (0, w) (x) q
//
// I_body = diag(I1, I2, I3) in the mass frame (see model.h), so products with I_w and I_w^-1 go
// through the body frame and never form a 3x3 world matrix:
//   I_w w      = R (I_body (R^T w))
//   I_w^-1 tau = R (I_body^-1 (R^T tau))
#include "physics/model.h"
#include "physics/passes.h"

namespace tumble::physics {

// R v for R the rotation of q / |q|, for the integrators that must keep |L| to round-off over
// 1e5 steps while converting w -> body momentum -> w every step (splitting, midpoint).
// Eigen's q * v assumes |q| = 1, but a normalised quaternion has |q|^2 = 1 + ~8e-17 on average
// (numbers just above 1 round twice as coarsely as those just below), and even with |q| = 1 the
// double-precision formula stretches vectors by ~3e-17 on average. Both biases have a fixed sign,
// so the round trip drifts |L| by ~2e-16 per step (2e-11 in 1e5 steps, measured). Here the scale
// 2 / |q|^2 and the final sum are evaluated in x87 extended precision (64-bit mantissa) and
// rounded once: the drift falls below 1e-13 in 1e5 steps (tests/physics/
// integrator_conservation_test.cpp). Deterministic like the rest (same binary, same bits).
inline Vec3 rotate(const Quat& q, const Vec3& v) {
    const Vec3 uv = q.vec().cross(v);
    const Vec3 t = q.w() * uv + q.vec().cross(uv); // R v = v + (2 / |q|^2) t
    const long double w = q.w(), x = q.x(), y = q.y(), z = q.z();
    const long double k = 2.0L / (w * w + x * x + y * y + z * z);
    return Vec3(static_cast<double>(v.x() + k * t.x()), static_cast<double>(v.y() + k * t.y()),
                static_cast<double>(v.z() + k * t.z()));
}
inline Vec3 to_body(const Quat& q, const Vec3& v) {
    return rotate(q.conjugate(), v);
}

// I_w w for a body with principal moments `inertia` at orientation q (unit).
inline Vec3 world_inertia_times(const Quat& q, const Vec3& inertia, const Vec3& w) {
    return q * inertia.cwiseProduct(q.conjugate() * w);
}

// I_w^-1 tau.
inline Vec3 world_inertia_inverse_times(const Quat& q, const Vec3& inv_inertia, const Vec3& tau) {
    return q * inv_inertia.cwiseProduct(q.conjugate() * tau);
}

// Change of angular velocity from an angular impulse J (world): dw = I_w^-1 J.
inline Vec3 angular_velocity_change(const Model& m, int i, const Quat& q, const Vec3& J) {
    if (!anisotropic(m, i)) return m.inv_inertia[i].x() * J;
    return world_inertia_inverse_times(q, m.inv_inertia[i], J);
}

// Euler's equation solved for the angular acceleration:
//   dw/dt = I_w^-1 (tau - w x I_w w)
// For an isotropic body w x I_w w = w x (I w) = 0 exactly, so that work is skipped.
inline Vec3 angular_acceleration(const Model& m, int i, const Quat& q, const Vec3& w,
                                 const Vec3& tau) {
    if (!anisotropic(m, i)) return m.inv_inertia[i].x() * tau;
    const Vec3 gyro = w.cross(world_inertia_times(q, m.inertia[i], w));
    return world_inertia_inverse_times(q, m.inv_inertia[i], tau - gyro);
}

} // namespace tumble::physics
