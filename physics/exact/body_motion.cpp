#include "physics/exact/body_motion.h"

#include <stdexcept>

namespace tumble::exact {

ExactBodyMotion::ExactBodyMotion(const physics::Model& m, const physics::State& s, int i) {
    if (!m.is_dynamic(i)) throw std::invalid_argument("a static body has no motion to predict");
    // sum F = m g s + F_applied (forces.h), read from the model itself rather than the passes.
    const Vec3 accel = m.gravity_scale[i] * m.gravity + m.inv_mass[i] * m.applied_force[i];
    translation_ = {s.x[i], s.v[i], accel};
    const Vec3& tau = m.applied_torque[i];
    if (tau == Vec3::Zero()) {
        free_.emplace(m.inertia[i], s.q[i], s.w[i]);
    } else if (m.isotropic[i]) {
        torqued_.emplace(m.inertia[i].x(), s.q[i], s.w[i], tau);
    } else {
        throw std::domain_error("a constant torque on a body with unequal moments has no closed "
                                "form here");
    }
}

BodyState ExactBodyMotion::at(double t) const {
    const RotationState r = free_ ? free_->state_at(t) : torqued_->state_at(t);
    return {translation_.x_at(t), r.q, translation_.v_at(t), r.w};
}

} // namespace tumble::exact
