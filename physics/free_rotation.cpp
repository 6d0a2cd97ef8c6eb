// The torque-free rigid body, exactly (free_rotation.h). Section numbers refer to
// docs/exact-solutions.md. Notation: m = I w_b (mass frame), |L| = |m|, 2E = m . I^-1 m; sn, cn, dn
// are Jacobi's functions of modulus k (parameter mc = 1 - k^2), F and Pi the incomplete elliptic
// integrals of the first and third kind,
//   F(phi, k)     = int_0^phi dt / sqrt(1 - k^2 sin^2 t)
//   Pi(n; phi, k) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - k^2 sin^2 t)),
// evaluated through Carlson's forms (DLMF 19.25.5 and 19.25.14), with s = sin phi, c = cos phi,
// D = 1 - k^2 s^2 = c^2 + mc s^2 (no cancellation near k = 1):
//   F(phi, k)     = s R_F(c^2, D, 1)
//   Pi(n; phi, k) = F(phi, k) + n/3 s^3 R_J(c^2, D, 1, 1 - n s^2)
// valid for |phi| <= pi/2; here n < 0, so 1 - n s^2 >= 1 and R_J is never singular.
#include "physics/free_rotation.h"

#include "physics/rigid_body.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace tumble::physics {
namespace {

using Wide = long double;
using Vec3L = Eigen::Matrix<Wide, 3, 1>;
using Mat3L = Eigen::Matrix<Wide, 3, 3>;

// The rotation B that takes the body momentum direction to e_z: rows (e1, e2, m^) with
// e1 = (e_r x m^) / |e_r x m^|, e2 = m^ x e1 (section 3.3). Needs m not along e_r.
Mat3L invariant_from_body(const Vec3L& m) {
    const Vec3L mh = m.normalized();
    const Wide rho = std::sqrt(mh.x() * mh.x() + mh.y() * mh.y());
    const Vec3L e1 = Vec3L(-mh.y(), mh.x(), 0) / rho;
    const Vec3L e2 = mh.cross(e1);
    Mat3L b;
    b.row(0) = e1.transpose();
    b.row(1) = e2.transpose();
    b.row(2) = mh.transpose();
    return b;
}

Mat3L rotation_z(Wide phi) {
    const Wide c = std::cos(phi), s = std::sin(phi);
    Mat3L z;
    z << c, -s, 0, s, c, 0, 0, 0, 1;
    return z;
}

using Real = double; // the elliptic scalars (free_rotation.h, "Rounding", says why not long double)

Real sign_of(Real x) {
    return x < 0 ? -1 : 1;
}

// Pi(n; am r, k) - F(am r, k) = n/3 sn^3 R_J(cn^2, dn^2, 1, 1 - n sn^2), for |r| <= K.
Real third_kind_excess(Real n, Real sn, Real cn2, Real dn2) {
    return n / 3 * sn * sn * sn * carlson_rj(cn2, dn2, Real(1), 1 - n * sn * sn);
}

// The same on the separatrix (k = 1, sn = tanh u, am u = gd u), in closed form: with s = sin t,
// Pi(n; phi, 1) = int_0^sin(phi) ds / ((1 - n s^2)(1 - s^2))
//              = (atanh(sin phi) + sqrt(-n) atan(sqrt(-n) sin phi)) / (1 - n)   (n < 0),
// and atanh(tanh u) = u, so Pi - u = (n u + sqrt(-n) atan(sqrt(-n) tanh u)) / (1 - n). Valid for
// every u, where Carlson's form would need cn^2 = dn^2 = sech^2 u, which underflows to 0 beyond
// |u| ~ 355 (a long step on the separatrix).
Real separatrix_excess(Real n, Real u) {
    const Real root = std::sqrt(-n);
    return (n * u + root * std::atan(root * std::tanh(u))) / (1 - n);
}

} // namespace

const char* free_regime_name(FreeRegime regime) {
    switch (regime) {
    case FreeRegime::Isotropic:
        return "isotropic";
    case FreeRegime::Axisymmetric:
        return "axisymmetric";
    case FreeRegime::PrincipalSpin:
        return "principal spin";
    case FreeRegime::AroundLargestAxis:
        return "around the largest axis";
    case FreeRegime::AroundSmallestAxis:
        return "around the smallest axis";
    }
    return "unknown";
}

FreeRotation::FreeRotation(const Vec3& inertia, const Quat& q0, const Vec3& w0)
    : inertia_(inertia), q0_(q0) {
    // The body momentum and back through rotate() (rigid_body.h): no bias of |L| per step.
    m0_ = inertia_.cwiseProduct(to_body(q0_, w0));
    L_world_ = rotate(q0_, m0_);
    energy_ = 0.5 * m0_.dot(m0_.cwiseQuotient(inertia_));
    L_norm_ = m0_.norm();
    separatrix_ = std::numeric_limits<double>::infinity();

    // Order the axes by moment: lo <= mid <= hi.
    int lo = 0, hi = 0;
    for (int a = 1; a < 3; ++a) {
        if (inertia_[a] < inertia_[lo]) lo = a;
        if (inertia_[a] > inertia_[hi]) hi = a;
    }
    if (lo == hi) hi = (lo + 1) % 3; // isotropic: any distinct pair
    const int mid = 3 - lo - hi;

    // Regular precession (section 2): two equal moments, or m along a principal axis (exact
    // zeros: m = 0 is such a case, and stays put).
    const Vec3& I = inertia_;
    int along = -1;
    for (int a = 0; a < 3; ++a)
        if (m0_[(a + 1) % 3] == 0.0 && m0_[(a + 2) % 3] == 0.0) along = a;
    if (I[lo] == I[hi]) {
        regime_ = FreeRegime::Isotropic;
        axis_s_ = 2;
        I_t_ = I[0];
    } else if (I[lo] == I[mid] || I[mid] == I[hi]) {
        regime_ = FreeRegime::Axisymmetric;
        axis_s_ = I[lo] == I[mid] ? hi : lo; // the distinct moment is the symmetry axis
        I_t_ = I[mid];
    } else if (along >= 0) {
        regime_ = FreeRegime::PrincipalSpin;
        axis_s_ = along;
        I_t_ = I[(along + 1) % 3]; // any value works: m stays along e_s (section 2)
    } else if (setup_jacobi(lo, mid, hi)) {
        return;
    } else {
        // The Jacobi quantities underflowed: the squares of two components of m vanish beside
        // the third's (m off a principal axis by less than ~1e-154 rad) or |L| itself is below
        // ~1e-154 (a body turning by less than that per second). The spin about the axis of the
        // largest component is then the motion to every digit a double holds.
        int a = 0;
        for (int b = 1; b < 3; ++b)
            if (std::abs(m0_[b]) > std::abs(m0_[a])) a = b;
        regime_ = FreeRegime::PrincipalSpin;
        axis_s_ = a;
        I_t_ = I[(a + 1) % 3];
        separatrix_ = std::numeric_limits<double>::infinity();
    }
    lambda_ = m0_[axis_s_] * (1.0 / I[axis_s_] - 1.0 / I_t_);
}

// Section 3, in the complementary parameter. The invariant differences are sums of squares with
// the vanishing term dropped exactly (section 3.1), and so is 1 - k^2:
//   mc = (I_r - I_p)(|L|^2 - 2E I_q) / ((I_r - I_q)(|L|^2 - 2E I_p)),
// because (I_r - I_q) a_p - (I_q - I_p) a_r = (I_r - I_p)(|L|^2 - 2E I_q) with
// a_r = 2E I_r - |L|^2, a_p = |L|^2 - 2E I_p. Every factor has the sign that makes mc >= 0.
bool FreeRotation::setup_jacobi(int lo, int mid, int hi) {
    const Vec3& I = inertia_;
    const auto sq = [&](int a) { return Real(m0_[a]) * m0_[a]; };
    const auto ratio = [&](int a, int b) { return Real(I[a]) / I[b]; };
    const Real sep = sq(lo) * (1 - ratio(mid, lo)) + sq(hi) * (1 - ratio(mid, hi));
    separatrix_ = double(std::abs(sep) / (Real(L_norm_) * L_norm_));
    const int p = sep >= 0 ? lo : hi, r = sep >= 0 ? hi : lo, q = mid;
    regime_ = sep >= 0 ? FreeRegime::AroundLargestAxis : FreeRegime::AroundSmallestAxis;
    P_.col(0) = Vec3::Unit(p);
    P_.col(1) = Vec3::Unit(q);
    P_.col(2) = Vec3::Unit(p).cross(Vec3::Unit(q)); // +-e_r: (p, q, r) is right-handed
    const Vec3 m = P_.transpose() * m0_;            // exact: P is a signed permutation
    const Real mp = m.x(), mq = m.y(), mr = m.z();
    const Real Ip = I[p], Iq = I[q], Ir = I[r];

    const Real a_r = mp * mp * (Ir / Ip - 1) + mq * mq * (Ir / Iq - 1);
    const Real a_p = mq * mq * (1 - Ip / Iq) + mr * mr * (1 - Ip / Ir);
    alpha_ = std::sqrt(Ip * a_r / (Ir - Ip));
    beta_ = std::sqrt(Iq * a_r / (Ir - Iq));
    k_ = std::sqrt(a_r * (Iq - Ip) / ((Ir - Iq) * a_p));
    nu_ = sign_of(mr) * sign_of(Ir - Iq) * std::sqrt(a_p * (Ir - Iq) / (Ip * Iq * Ir));
    n_ = -Ir * (Iq - Ip) / (Ip * (Ir - Iq));
    ladder_ = agm_ladder((Ir - Ip) * sep / ((Ir - Iq) * a_p)); // sep = |L|^2 - 2E I_q
    K_ = complete_k(ladder_);

    // The phase (section 3.2): cn u0 = m_p / alpha, sn u0 = m_q / beta. With m_p < 0 the state is
    // on the other half of the orbit (on the separatrix, the other heteroclinic orbit): Euler's
    // equations are invariant under m -> diag(-1, -1, 1) m (a half turn about e_r), so we follow
    // the mirrored state from r0 in [-K, K], where the amplitude is in [-pi/2, pi/2] and
    // F(am r0) = r0, and mirror back (flip_ = -1; the k < 1 case of u0 + 2K).
    flip_ = mp < 0 ? -1 : 1;
    const Real c_raw = flip_ * mp / alpha_, s_raw = flip_ * mq / beta_;
    const Real h = std::sqrt(c_raw * c_raw + s_raw * s_raw);
    const Real c0 = c_raw / h, s0 = s_raw / h;
    const Real d0 = c0 * c0 + ladder_.mc * s0 * s0; // dn^2 = 1 - k^2 sn^2
    if (!(alpha_ > 0 && beta_ > 0 && d0 > 0 && std::isfinite(c0 + s0 + nu_ + ladder_.mc)))
        return false; // underflow (the constructor says when)
    // The amplitudes anchored to the state: alpha cn u0 = m_p, beta sn u0 = m_q, gamma dn u0 = m_r
    // to rounding. From the invariants alone they would carry the rounding of constants made
    // from I (I_r / I_p - 1, ...), the same every step. Anchored, the reconstruction is exact at
    // t = 0 and its error at t is (sn^2 u - sn^2 u0) times the identities' violation (|m|^2 and
    // 2E are both A + B sn^2 u along the solution), a sum that telescopes over the steps.
    alpha_ *= h;
    beta_ *= h;
    gamma_ = mr / std::sqrt(d0);
    r0_ = s0 * carlson_rf(c0 * c0, d0, Real(1));
    const Jacobi<Real> e0 = jacobi(r0_, ladder_);
    m_pqr0_ = Vec3(mp, mq, mr);
    mtilde0_ = Vec3(flip_ * alpha_ * e0.cn, flip_ * beta_ * e0.sn, gamma_ * e0.dn);
    Pi0_ = r0_ +
           (ladder_.mc == 0 ? separatrix_excess(n_, r0_) : third_kind_excess(n_, s0, c0 * c0, d0));
    phi_rate_ = L_norm_ / Ir;
    phi_pi_ = L_norm_ * (Ir - Ip) / (Ir * Ip * nu_);

    // Invariant frame (section 3.3): R_pqr(t) = W Z(phi(t)) B(m(t)), W = R0 B(m0)^T, phi(0) = 0.
    B0t_ = invariant_from_body(Vec3L(mp, mq, mr)).transpose();
    return true;
}

// u = r0 + nu t = 2 K j + r with |r| <= K (section 3.4): sn, cn change sign with j, dn does not,
// and Pi(n; am u) = 2 j Pi(n, k) + Pi(n; am r). On the separatrix K is infinite and j = 0.
FreeRotation::JacobiPoint FreeRotation::jacobi_point(double t) const {
    const Real u = r0_ + nu_ * t;
    const Real j = ladder_.mc == 0 ? 0 : std::nearbyint(u / (2 * K_));
    const Real r = j == 0 ? u : u - 2 * K_ * j;
    const Jacobi<Real> e = jacobi(r, ladder_);
    const Real sign = std::fmod(j, Real(2)) == 0 ? flip_ : -flip_;
    JacobiPoint out;
    // m(t) = m(0) + (mtilde(u) - mtilde(r0)): the increment along the solution added to the state
    // itself, so that the biased rounding of r0 = F(am u0) and of sn, cn, dn enters only in
    // proportion to the increment (free_rotation.h, "Rounding").
    const Vec3 mt(sign * alpha_ * e.cn, sign * beta_ * e.sn, gamma_ * e.dn);
    out.m = m_pqr0_.cast<Wide>() + (mt - mtilde0_).cast<Wide>();
    const Real excess = ladder_.mc == 0 ? separatrix_excess(n_, r)
                                        : third_kind_excess(n_, e.sn, e.cn * e.cn, e.dn * e.dn);
    Real dPi = r + excess - Pi0_;
    if (j != 0) // the complete Pi(n, k) = K + n/3 R_J(0, mc, 1, 1 - n), only when crossed
        dPi += 2 * j * (K_ + n_ / 3 * carlson_rj(Real(0), ladder_.mc, Real(1), 1 - n_));
    // Section 3.4: phi(t) = |L| t / I_r + |L| (I_r - I_p) / (I_r I_p nu) (Pi(am u) - Pi(am u0)).
    out.phi = phi_rate_ * t + phi_pi_ * dPi;
    return out;
}

Vec3 FreeRotation::body_momentum_at(double t) const {
    if (is_jacobi()) return P_ * jacobi_point(t).m.cast<double>();
    // m(t) = exp(-lambda t e_s) m0: m turns about the symmetry axis at rate -lambda.
    return Eigen::AngleAxisd(-lambda_ * t, Vec3::Unit(axis_s_)) * m0_;
}

FreeState FreeRotation::at(double t) const {
    return is_jacobi() ? jacobi_state(t) : precession_state(t);
}

FreeState FreeRotation::precession_state(double t) const {
    // Section 2: R(t) = exp(t L / I_t) R0 exp(lambda t e_s), w = L / I_t + lambda R(t) e_s.
    const Quat q =
        (quat_exp(t / I_t_ * L_world_) * q0_ * quat_exp(lambda_ * t * Vec3::Unit(axis_s_)))
            .normalized();
    return {q, L_world_ / I_t_ + lambda_ * rotate(q, Vec3::Unit(axis_s_))};
}

// Section 3.5: R_mass = W Z(phi) B(m) P^T with W = R0 P B(m0)^T, that is R = R0 Q with the
// rotation since t = 0, Q = P B(m0)^T Z(phi) B(m) P^T, formed in long double and applied to q0 as
// a quaternion with one rounding: q0 never makes the trip to a matrix and back (in double that
// trip, and Q, turned a body by 1.2e-10 rad in 1e6 steps of 1e-7 s; 6.5e-11 now, measured).
// w = R I^-1 (P m).
FreeState FreeRotation::jacobi_state(double t) const {
    const JacobiPoint j = jacobi_point(t);
    const Mat3L Pl = P_.cast<Wide>();
    const Mat3L Q = Pl * B0t_ * rotation_z(j.phi) * invariant_from_body(j.m) * Pl.transpose();
    const Eigen::Quaternion<Wide> q = (q0_.cast<Wide>() * Eigen::Quaternion<Wide>(Q)).normalized();
    const Quat qd = q.cast<double>();
    const Vec3 m = P_ * j.m.cast<double>();
    return {qd, rotate(qd, m.cwiseQuotient(inertia_))};
}

double FreeRotation::body_period() const {
    if (is_jacobi()) return double(4 * K_ / std::abs(nu_));
    const bool constant =
        lambda_ == 0.0 || (m0_[(axis_s_ + 1) % 3] == 0.0 && m0_[(axis_s_ + 2) % 3] == 0.0);
    return constant ? std::numeric_limits<double>::infinity()
                    : 2.0 * std::numbers::pi / std::abs(lambda_);
}

} // namespace tumble::physics
