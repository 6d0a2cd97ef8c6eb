// The torque-free rigid body, exactly. Derivation and sign checks: docs/exact-solutions.md (the
// section numbers below refer to it). Notation: m = I w_body (mass frame), L = |m|,
// 2E = m . I^-1 m, sn/cn/dn are Jacobi's elliptic functions of modulus k, F and Pi the incomplete
// elliptic integrals of the first and third kind with Boost's conventions:
//   F(phi, k)     = int_0^phi dt / sqrt(1 - k^2 sin^2 t)
//   Pi(n; phi, k) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - k^2 sin^2 t))
#include "physics/exact/free_rigid_body.h"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace tumble::exact {
namespace {

constexpr double kPi = std::numbers::pi;

struct Elliptic {
    double sn, cn, dn; // at u
    double Pi;         // Pi(n; am(u), k), am(u) the amplitude, continuous and increasing in u
};

// sn, cn, dn and Pi(n; am u, k) for any real u (section 3.4). With u = 2 K j + r, |r| <= K:
// sn(u) = (-1)^j sn(r), cn(u) = (-1)^j cn(r), dn(u) = dn(r), am(u) = j pi + am(r) and
// Pi(n; am u) = 2 j Pi(n, k) + Pi(n; am r), because the integrand of Pi has period pi.
Elliptic elliptic_at(double u, double k, double K, double n, double Pi_complete) {
    const double j = std::nearbyint(u / (2.0 * K));
    const double r = u - 2.0 * K * j;
    double cn = 0.0, dn = 0.0;
    const double sn = boost::math::jacobi_elliptic(k, r, &cn, &dn);
    const double am_r = std::atan2(sn, cn); // in [-pi/2, pi/2] since cn(r) >= 0 for |r| <= K
    const double sign = std::fmod(j, 2.0) == 0.0 ? 1.0 : -1.0;
    return {sign * sn, sign * cn, dn, 2.0 * j * Pi_complete + boost::math::ellint_3(k, n, am_r)};
}

// F(phi, k) for any real phi: phi = j pi + rho, |rho| <= pi/2, F = 2 j K + F(rho, k).
double ellint_1_any(double k, double phi, double K) {
    const double j = std::nearbyint(phi / kPi);
    return 2.0 * j * K + boost::math::ellint_1(k, phi - j * kPi);
}

// The rotation B that takes the body momentum direction to e_z: rows (e1, e2, m^) with
// e1 = (e_r x m^) / |e_r x m^|, e2 = m^ x e1 (section 3.5). Needs m not along e_r.
Mat3 invariant_from_body(const Vec3& m) {
    const Vec3 mh = m.normalized();
    const double rho = std::hypot(mh.x(), mh.y());
    const Vec3 e1 = Vec3(-mh.y(), mh.x(), 0.0) / rho;
    const Vec3 e2 = mh.cross(e1);
    Mat3 b;
    b.row(0) = e1.transpose();
    b.row(1) = e2.transpose();
    b.row(2) = mh.transpose();
    return b;
}

Mat3 rotation_z(double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    Mat3 z;
    z << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
    return z;
}

double sign_of(double x) {
    return x < 0.0 ? -1.0 : 1.0;
}

} // namespace

const char* regime_name(ExactFreeRigidBody::Regime regime) {
    switch (regime) {
    case ExactFreeRigidBody::Regime::Isotropic:
        return "isotropic";
    case ExactFreeRigidBody::Regime::Axisymmetric:
        return "axisymmetric";
    case ExactFreeRigidBody::Regime::PrincipalSpin:
        return "principal spin";
    case ExactFreeRigidBody::Regime::AroundLargestAxis:
        return "around the largest axis";
    case ExactFreeRigidBody::Regime::AroundSmallestAxis:
        return "around the smallest axis";
    }
    return "unknown";
}

ExactFreeRigidBody::ExactFreeRigidBody(const Vec3& inertia, const Quat& q0, const Vec3& w0)
    : inertia_(inertia) {
    if (!inertia.allFinite() || inertia.minCoeff() <= 0.0)
        throw std::invalid_argument("principal moments must be positive and finite");
    if (!q0.coeffs().allFinite() || q0.norm() == 0.0 || !w0.allFinite())
        throw std::invalid_argument("initial orientation and angular velocity must be finite");
    q0_ = q0.normalized();
    m0_ = inertia_.cwiseProduct(q0_.conjugate() * w0);
    L_world_ = q0_ * m0_;
    energy_ = 0.5 * m0_.dot(m0_.cwiseQuotient(inertia_));
    L_norm_ = m0_.norm();

    // Order the axes by moment: lo <= mid <= hi.
    int lo = 0, hi = 0;
    for (int a = 1; a < 3; ++a) {
        if (inertia_[a] < inertia_[lo]) lo = a;
        if (inertia_[a] > inertia_[hi]) hi = a;
    }
    if (lo == hi) hi = (lo + 1) % 3; // isotropic: any distinct pair
    const int mid = 3 - lo - hi;

    // Regular precession (section 2): two equal moments, or m along a principal axis.
    const Vec3& I = inertia_;
    int along = -1;
    for (int a = 0; a < 3; ++a)
        if (m0_[(a + 1) % 3] == 0.0 && m0_[(a + 2) % 3] == 0.0) along = a;
    if (I[lo] == I[hi]) {
        regime_ = Regime::Isotropic;
        axis_s_ = 2;
        I_t_ = I[0];
    } else if (I[lo] == I[mid] || I[mid] == I[hi]) {
        regime_ = Regime::Axisymmetric;
        axis_s_ = I[lo] == I[mid] ? hi : lo; // the distinct moment is the symmetry axis
        I_t_ = I[mid];
    } else if (along >= 0) {
        regime_ = Regime::PrincipalSpin;
        axis_s_ = along;
        I_t_ = I[(along + 1) % 3]; // any value works: m stays along e_s (section 2)
    }
    const bool precession = I[lo] == I[mid] || I[mid] == I[hi] || along >= 0;
    if (precession) {
        lambda_ = m0_[axis_s_] * (1.0 / I[axis_s_] - 1.0 / I_t_);
        return;
    }

    // Jacobi regimes (section 3). Sign of |L|^2 - 2 E I_mid, computed without cancellation:
    // sum_a m_a^2 (1 - I_mid / I_a), in which the middle axis drops out exactly.
    const auto sq = [&](int a) { return m0_[a] * m0_[a]; };
    const double sep = sq(lo) * (1.0 - I[mid] / I[lo]) + sq(hi) * (1.0 - I[mid] / I[hi]);
    if (std::abs(sep) <= 1e-12 * L_norm_ * L_norm_)
        throw std::domain_error("the motion lies on the separatrix |L|^2 = 2 E I_mid (k = 1), "
                                "which this oracle excludes");
    const int p = sep > 0.0 ? lo : hi, r = sep > 0.0 ? hi : lo, q = mid;
    regime_ = sep > 0.0 ? Regime::AroundLargestAxis : Regime::AroundSmallestAxis;
    P_.col(0) = Vec3::Unit(p);
    P_.col(1) = Vec3::Unit(q);
    P_.col(2) = Vec3::Unit(p).cross(Vec3::Unit(q)); // +-e_r: (p, q, r) is right-handed
    I_pqr_ = Vec3(I[p], I[q], I[r]);
    const Vec3 m = P_.transpose() * m0_;
    const double Ip = I_pqr_.x(), Iq = I_pqr_.y(), Ir = I_pqr_.z();

    // 2 E I_r - |L|^2 and |L|^2 - 2 E I_p, again with the vanishing term dropped exactly.
    const double a_r = m.x() * m.x() * (Ir / Ip - 1.0) + m.y() * m.y() * (Ir / Iq - 1.0);
    const double a_p = m.y() * m.y() * (1.0 - Ip / Iq) + m.z() * m.z() * (1.0 - Ip / Ir);
    alpha_ = std::sqrt(Ip * a_r / (Ir - Ip));
    beta_ = std::sqrt(Iq * a_r / (Ir - Iq));
    gamma_ = sign_of(m.z()) * std::sqrt(Ir * a_p / (Ir - Ip));
    k_ = std::sqrt(a_r * (Iq - Ip) / ((Ir - Iq) * a_p));
    nu_ = sign_of(m.z()) * sign_of(Ir - Iq) * std::sqrt(a_p * (Ir - Iq) / (Ip * Iq * Ir));
    n_ = -Ir * (Iq - Ip) / (Ip * (Ir - Iq));
    K_ = boost::math::ellint_1(k_);
    Pi_complete_ = boost::math::ellint_3(k_, n_);
    u0_ = ellint_1_any(k_, std::atan2(m.y() / beta_, m.x() / alpha_), K_);
    Pi0_ = elliptic_at(u0_, k_, K_, n_, Pi_complete_).Pi;
    phi_rate_ = L_norm_ / Ir;
    phi_pi_ = L_norm_ * (Ir - Ip) / (Ir * Ip * nu_);

    // Invariant frame (section 3.5): R_pqr(t) = W Z(phi(t)) B(m(t)) with phi(0) = 0.
    const Mat3 R0 = q0_.toRotationMatrix();
    W_ = R0 * P_ * invariant_from_body(jacobi_body_momentum(u0_)).transpose();
}

Vec3 ExactFreeRigidBody::jacobi_body_momentum(double u) const {
    const Elliptic e = elliptic_at(u, k_, K_, n_, Pi_complete_);
    return Vec3(alpha_ * e.cn, beta_ * e.sn, gamma_ * e.dn);
}

Vec3 ExactFreeRigidBody::body_momentum_at(double t) const {
    if (regime_ == Regime::AroundLargestAxis || regime_ == Regime::AroundSmallestAxis)
        return P_ * jacobi_body_momentum(u0_ + nu_ * t);
    // m(t) = exp(-lambda t e_s) m0: m turns about the symmetry axis at rate -lambda.
    return Eigen::AngleAxisd(-lambda_ * t, Vec3::Unit(axis_s_)) * m0_;
}

RotationState ExactFreeRigidBody::state_at(double t) const {
    if (regime_ == Regime::AroundLargestAxis || regime_ == Regime::AroundSmallestAxis)
        return jacobi_state(t);
    return precession_state(t);
}

RotationState ExactFreeRigidBody::precession_state(double t) const {
    // Section 2: R(t) = exp(t L / I_t) R0 exp(lambda t e_s), w = L / I_t + lambda R(t) e_s.
    const Quat q = (physics::quat_exp(t / I_t_ * L_world_) * q0_ *
                    physics::quat_exp(lambda_ * t * Vec3::Unit(axis_s_)))
                       .normalized();
    return {q, L_world_ / I_t_ + lambda_ * (q * Vec3::Unit(axis_s_))};
}

RotationState ExactFreeRigidBody::jacobi_state(double t) const {
    const double u = u0_ + nu_ * t;
    const Elliptic e = elliptic_at(u, k_, K_, n_, Pi_complete_);
    const Vec3 m(alpha_ * e.cn, beta_ * e.sn, gamma_ * e.dn);
    // Section 3.5: phi(t) = |L| t / I_r + |L| (I_r - I_p) / (I_r I_p nu) (Pi(am u) - Pi(am u0)).
    const double phi = phi_rate_ * t + phi_pi_ * (e.Pi - Pi0_);
    const Mat3 R = W_ * rotation_z(phi) * invariant_from_body(m) * P_.transpose();
    const Quat q = Quat(R).normalized();
    return {q, q * (P_ * m).cwiseQuotient(inertia_)};
}

double ExactFreeRigidBody::body_period() const {
    if (regime_ == Regime::AroundLargestAxis || regime_ == Regime::AroundSmallestAxis)
        return 4.0 * K_ / std::abs(nu_);
    const bool constant =
        lambda_ == 0.0 || (m0_[(axis_s_ + 1) % 3] == 0.0 && m0_[(axis_s_ + 2) % 3] == 0.0);
    return constant ? std::numeric_limits<double>::infinity() : 2.0 * kPi / std::abs(lambda_);
}

} // namespace tumble::exact
