#include "physics/math.h"

#include <cmath>

namespace tumble::physics {

Quat quat_exp(const Vec3& phi) {
    const double angle = phi.norm();
    const double half = 0.5 * angle;
    // sin(half)/angle = 1/2 sinc(half); series 1/2 (1 - half^2/6 + half^4/120) for small angles.
    double s;
    if (angle < 1e-4) {
        const double h2 = half * half;
        s = 0.5 * (1.0 - h2 / 6.0 + h2 * h2 / 120.0);
    } else {
        s = std::sin(half) / angle;
    }
    return Quat(std::cos(half), s * phi.x(), s * phi.y(), s * phi.z());
}

Vec3 quat_log(const Quat& q_in) {
    // Use the representative with w >= 0 so that the angle lies in [0, pi].
    Quat q = q_in.w() < 0.0 ? Quat(-q_in.w(), -q_in.x(), -q_in.y(), -q_in.z()) : q_in;
    const double s = q.vec().norm();
    const double angle = 2.0 * std::atan2(s, q.w());
    if (s < 1e-12) return 2.0 * q.vec(); // angle ~ 2 s: first-order inverse, exact to round-off
    return (angle / s) * q.vec();
}

double rotation_angle_between(const Quat& a, const Quat& b) {
    return quat_log(a.conjugate() * b).norm();
}

} // namespace tumble::physics
