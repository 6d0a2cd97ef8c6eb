#include "physics/exact/simple_motions.h"

#include <cmath>
#include <stdexcept>

namespace tumble::exact {

ConstantTorqueSphere::ConstantTorqueSphere(double inertia, const Quat& q0, const Vec3& w0,
                                           const Vec3& tau)
    : inertia_(inertia), q0_(q0.normalized()), w0_(w0), tau_(tau) {
    if (!(std::isfinite(inertia) && inertia > 0.0))
        throw std::invalid_argument("the sphere's moment of inertia must be positive and finite");
    if (w0.cross(tau).norm() > 1e-12 * w0.norm() * tau.norm())
        throw std::domain_error("constant torque on a sphere: w0 must be parallel to the torque "
                                "(otherwise the orientation has no closed form)");
}

RotationState ConstantTorqueSphere::state_at(double t) const {
    const Vec3 angle = t * w0_ + (0.5 * t * t / inertia_) * tau_;
    return {(physics::quat_exp(angle) * q0_).normalized(), w0_ + (t / inertia_) * tau_};
}

} // namespace tumble::exact
