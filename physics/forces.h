#pragma once
// External loads on body i, constant over a step (gravity and the scene's applied loads):
//   sum F = m g s + F_applied        (s: the body's gravity scale)
//   sum tau = tau_applied
// Contact impulses are not loads; the contact stage applies them to the velocities.
#include "physics/model.h"

namespace tumble::physics {

inline Vec3 net_force(const Model& m, int i) {
    return m.mass[i] * m.gravity_scale[i] * m.gravity + m.applied_force[i];
}

inline Vec3 net_torque(const Model& m, int i) {
    return m.applied_torque[i];
}

} // namespace tumble::physics
