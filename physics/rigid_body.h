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

namespace tumble::physics {

// I_w w for a body with principal moments `inertia` at orientation q (unit).
inline Vec3 world_inertia_times(const Quat& q, const Vec3& inertia, const Vec3& w) {
    return q * inertia.cwiseProduct(q.conjugate() * w);
}

// I_w^-1 tau.
inline Vec3 world_inertia_inverse_times(const Quat& q, const Vec3& inv_inertia, const Vec3& tau) {
    return q * inv_inertia.cwiseProduct(q.conjugate() * tau);
}

// Euler's equation solved for the angular acceleration:
//   dw/dt = I_w^-1 (tau - w x I_w w)
// For an isotropic body w x I_w w = w x (I w) = 0 exactly, so that work is skipped.
inline Vec3 angular_acceleration(const Model& m, int i, const Quat& q, const Vec3& w,
                                 const Vec3& tau) {
    if (m.isotropic[i]) return m.inv_inertia[i].x() * tau;
    const Vec3 gyro = w.cross(world_inertia_times(q, m.inertia[i], w));
    return world_inertia_inverse_times(q, m.inv_inertia[i], tau - gyro);
}

} // namespace tumble::physics
