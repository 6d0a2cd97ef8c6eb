// The oracle's checks around physics::FreeRotation (free_rigid_body.h).
#include "physics/exact/free_rigid_body.h"

#include <stdexcept>

namespace tumble::exact {
namespace {

// The constructor's checks run before the motion is built, so that FreeRotation only ever sees
// positive moments, a unit quaternion and a finite w.
const Vec3& checked_inertia(const Vec3& inertia) {
    if (!inertia.allFinite() || inertia.minCoeff() <= 0.0)
        throw std::invalid_argument("principal moments must be positive and finite");
    return inertia;
}

Quat checked_orientation(const Quat& q0, const Vec3& w0) {
    if (!q0.coeffs().allFinite() || q0.norm() == 0.0 || !w0.allFinite())
        throw std::invalid_argument("initial orientation and angular velocity must be finite");
    return q0.normalized();
}

} // namespace

const char* regime_name(ExactFreeRigidBody::Regime regime) {
    return physics::free_regime_name(regime);
}

ExactFreeRigidBody::ExactFreeRigidBody(const Vec3& inertia, const Quat& q0, const Vec3& w0)
    : motion_(checked_inertia(inertia), checked_orientation(q0, w0), w0) {
    if (motion_.separatrix_distance() <= 1e-12)
        throw std::domain_error("the motion lies on the separatrix |L|^2 = 2 E I_mid (k = 1), "
                                "which this oracle excludes");
}

RotationState ExactFreeRigidBody::state_at(double t) const {
    const physics::FreeState s = motion_.at(t);
    return {s.q, s.w};
}

} // namespace tumble::exact
