#pragma once
// External loads on body i, constant over a step (gravity and the scene's applied loads):
//   sum F = m g s + F_applied        (s: the body's gravity scale)
//   sum tau = tau_applied
// Each term is added only when its pass is on (passes.h): a scene without gravity never touches g.
// Contact impulses are not loads; the contact stage applies them to the velocities.
#include "physics/model.h"

namespace tumble::physics {

inline Vec3 net_force(const Model& m, int i) {
    Vec3 f = Vec3::Zero();
    if (m.passes.gravity) f += m.mass[i] * m.gravity_scale[i] * m.gravity;
    if (m.passes.applied_loads) f += m.applied_force[i];
    return f;
}

inline Vec3 net_torque(const Model& m, int i) {
    return m.passes.applied_loads ? m.applied_torque[i] : Vec3::Zero();
}

} // namespace tumble::physics
