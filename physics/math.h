#pragma once
// Small vector and rotation helpers on top of Eigen. Notation follows the course notes:
// [a]x is the skew matrix with [a]x b = a x b; q (x) p is the quaternion product.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <limits>

namespace tumble::physics {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

// No bound: the reach of a plane, the separation before any axis is tried, the time to a contact
// that cannot happen.
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// [a]x = [[0, -az, ay], [az, 0, -ax], [-ay, ax, 0]]
inline Mat3 skew(const Vec3& a) {
    Mat3 m;
    m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
    return m;
}

// exp of the rotation vector phi: the unit quaternion (cos(|phi|/2), sin(|phi|/2) phi/|phi|).
// Exact for any angle; below 1e-4 rad the Taylor series keeps sin(x)/x accurate to round-off.
Quat quat_exp(const Vec3& phi);

// Rotation vector of a unit quaternion (inverse of quat_exp), angle in [0, pi].
Vec3 quat_log(const Quat& q);

// Angle of the rotation between two orientations, |log(a^-1 b)|, in [0, pi] radians.
double rotation_angle_between(const Quat& a, const Quat& b);

// Quaternion time derivative for world angular velocity w: dq/dt = 1/2 (0, w) (x) q.
inline Quat quat_derivative(const Vec3& w, const Quat& q) {
    const Quat wq = Quat(0.0, w.x(), w.y(), w.z()) * q;
    return Quat(0.5 * wq.w(), 0.5 * wq.x(), 0.5 * wq.y(), 0.5 * wq.z());
}

inline bool all_finite(const Vec3& v) {
    return v.allFinite();
}
inline bool all_finite(const Quat& q) {
    return q.coeffs().allFinite();
}

} // namespace tumble::physics
