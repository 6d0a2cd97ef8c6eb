#pragma once
// The exact motion of a torque-free rigid body (Euler 1758, Jacobi 1849): the flow the `exact`
// and `splitting_exact` integrators take every step, and the oracle of physics/exact
// (ExactFreeRigidBody wraps this class: one implementation, so the integrators' own tests compare
// them with references written in the tests instead). The derivation, with every sign checked, is
// docs/exact-solutions.md, whose section numbers the .cpp cites.
//
// Conventions are the simulator's (state.h): q is the orientation of the mass frame (principal
// axes, moments I = diag(I1, I2, I3)), body -> world; w is the world angular velocity;
// m = I w_b is the body angular momentum (mass frame) and L = R m the world one.
//
// Regimes (FreeRegime): Isotropic, Axisymmetric and PrincipalSpin are regular precessions
// (trigonometric functions only); AroundLargestAxis and AroundSmallestAxis move m by Jacobi's sn,
// cn, dn and the orientation by the elliptic integral of the third kind, in the complementary
// parameter mc = 1 - k^2 (elliptic.h), so that the motions close to the separatrix
// |L|^2 = 2 E I_mid (k -> 1, where the intermediate-axis flips live) keep full accuracy and the
// separatrix itself (mc = 0: sn = tanh, cn = dn = sech, an infinite period) is its own limit, not
// an error. Construction and evaluation never allocate and never throw; the caller gives positive
// finite moments, a unit quaternion and a finite w (the oracle checks, step() checks the states).
#include "physics/elliptic.h"
#include "physics/math.h"

#include <cstdint>

namespace tumble::physics {

enum class FreeRegime : std::uint8_t {
    Isotropic,
    Axisymmetric,
    PrincipalSpin,
    AroundLargestAxis,
    AroundSmallestAxis,
};
const char* free_regime_name(FreeRegime regime);

struct FreeState {
    Quat q; // mass frame, body -> world (unit)
    Vec3 w; // world angular velocity, rad/s
};

class FreeRotation {
  public:
    FreeRotation(const Vec3& inertia, const Quat& q0, const Vec3& w0);

    FreeState at(double t) const;          // the state t seconds after (q0, w0), any real t
    Vec3 body_momentum_at(double t) const; // m(t), mass frame

    FreeRegime regime() const { return regime_; }
    Vec3 angular_momentum() const { return L_world_; } // world, constant
    double energy() const { return energy_; }          // 1/2 m . I^-1 m, constant
    double modulus() const { return double(k_); }      // k (0 outside the Jacobi regimes)
    double complementary_parameter() const { return double(ladder_.mc); } // 1 - k^2
    // |(|L|^2 - 2 E I_mid)| / |L|^2: the relative distance from the separatrix (Jacobi regimes;
    // infinity for the others, which have no separatrix).
    double separatrix_distance() const { return separatrix_; }
    // Period of m(t) in the body frame: 4 K / |nu| (Jacobi), 2 pi / |lambda| (precession),
    // infinity when m is constant or on the separatrix.
    double body_period() const;

  private:
    bool is_jacobi() const { return regime_ >= FreeRegime::AroundLargestAxis; }
    void setup_jacobi(int lo, int mid, int hi);
    struct JacobiPoint {
        Eigen::Matrix<long double, 3, 1> m; // body momentum, (p, q, r) frame
        long double phi; // angle about L of the invariant frame (section 3.3), rad
    };
    JacobiPoint jacobi_point(double t) const;
    FreeState precession_state(double t) const;
    FreeState jacobi_state(double t) const;

    Vec3 inertia_;
    Quat q0_;
    Vec3 m0_;      // body momentum at t = 0, mass frame
    Vec3 L_world_; // world angular momentum
    double energy_ = 0.0, L_norm_ = 0.0;
    double separatrix_ = 0.0;
    FreeRegime regime_ = FreeRegime::Isotropic;

    // Regular precession (section 2): R(t) = exp(t L / I_t) R0 exp(lambda t e_s).
    int axis_s_ = 2;
    double I_t_ = 1.0, lambda_ = 0.0;

    // Jacobi regimes (section 3) in the right-handed frame (p, q, r), m_mass = P m_pqr:
    // m_pqr(t) = s (alpha cn u, beta sn u, gamma dn u) with u = r0 + nu t, where s = diag(f, f, 1)
    // and f = +-1 picks the half of the orbit the state is on (see setup_jacobi). The scalars are
    // long double (x87, 64-bit mantissa), like rigid_body.h's rotate(): every rounding of them
    // that has a preferred sign (numbers just below 1 round more finely than those above, a
    // truncated series errs one way) would otherwise move E and |L| by the same ~1e-17 every step,
    // a linear drift (4e-12 in 1e5 steps of the flipping book, measured in double).
    using Real = long double;
    Mat3 P_ = Mat3::Identity();
    Real alpha_ = 0, beta_ = 0, gamma_ = 0, flip_ = 1;
    Real k_ = 0, nu_ = 0, n_ = 0;
    AgmLadder<Real> ladder_;
    Real K_ = 0;                     // complete K(k), infinite on the separatrix
    Real r0_ = 0;                    // u at t = 0, in [-K, K]
    Real Pi0_ = 0;                   // Pi(n; am r0, k)
    Real phi_rate_ = 0, phi_pi_ = 0; // phi(t) = phi_rate t + phi_pi (Pi(am u) - Pi0)
    Eigen::Matrix<Real, 3, 3> B0t_;  // B(m0)^T: the invariant frame W = R0 P B(m0)^T (section 3.3)
};

} // namespace tumble::physics
