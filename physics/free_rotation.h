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
    bool setup_jacobi(int lo, int mid, int hi); // false if its quantities underflow
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
    // and f = +-1 picks the half of the orbit the state is on (see setup_jacobi).
    //
    // Rounding. A step of `exact` is a FreeRotation made from the state and evaluated once, so any
    // rounding with a preferred sign repeats every step and accumulates linearly: numbers just
    // below 1 round more finely than those above, constants made from I carry one fixed rounding,
    // and the inverse r0 = F(am u0) followed by sn(r0) does not return the state exactly (0.05 ulp
    // on average). Evaluated plainly, |L| and E drifted by -4.4e-17 per step (-4.4e-12 in 1e5
    // steps of the flipping book, measured). So the amplitudes are anchored to the state, m(t) is
    // the state plus the increment mtilde(u) - mtilde(r0) of the solution (the biases cancel in the
    // difference), and the rotation since t = 0 is formed in long double and applied to q0 as a
    // quaternion (q0 never goes to a matrix and back). Now E and |L| random-walk (7e-14 after 1e5
    // steps) and a body's angle errs by 6.5e-11 rad after 1e6 steps of 1e-7 s, against 1e-12 to
    // 2.5e-11 for the other methods (tests/physics/extremes_test.cpp). All of it in long double
    // erred ten times less on the tiny steps but cost twice as much (2 us a step, not 0.9).
    Mat3 P_ = Mat3::Identity();
    Vec3 m_pqr0_, mtilde0_; // m(0) in (p, q, r), and the solution's own value at u = r0
    double alpha_ = 0, beta_ = 0, gamma_ = 0, flip_ = 1;
    double k_ = 0, nu_ = 0, n_ = 0;
    AgmLadder<double> ladder_;
    double K_ = 0;                         // complete K(k), infinite on the separatrix
    double r0_ = 0;                        // u at t = 0, in [-K, K]
    double Pi0_ = 0;                       // Pi(n; am r0, k)
    double phi_rate_ = 0, phi_pi_ = 0;     // phi(t) = phi_rate t + phi_pi (Pi(am u) - Pi0)
    Eigen::Matrix<long double, 3, 3> B0t_; // B(m0)^T: W = R0 P B(m0)^T (section 3.3)
};

} // namespace tumble::physics
