#pragma once
// The exact motion of a torque-free rigid body (Euler 1758, Jacobi 1849), as an oracle for tests,
// benchmarks and `tumble study`. The derivation, with every sign checked, is in
// docs/exact-solutions.md; the tests in tests/physics/exact_free_body_test.cpp check that the
// result satisfies Euler's equations and dq/dt = 1/2 (0, w) (x) q by finite differences, keeps
// energy and world angular momentum, and agrees with a very fine Runge-Kutta integration.
//
// Conventions are the simulator's (physics/state.h): q is the orientation of the *mass frame*
// (principal axes, moments I = diag(I1, I2, I3)), body -> world; w is the angular velocity in the
// world frame. m = I w_body is the angular momentum in the mass frame, L = R m in the world.
//
// Regimes:
//   Isotropic, Axisymmetric (two equal moments) and PrincipalSpin (m along a principal axis):
//     closed form with trigonometric functions only (regular precession).
//   AroundLargestAxis, AroundSmallestAxis (three distinct moments): m(t) by Jacobi's sn, cn, dn,
//     the orientation by the incomplete elliptic integral of the third kind. This covers the
//     intermediate-axis flip (Dzhanibekov) motion, which is one of the two regimes with modulus k
//     close to 1. The separatrix itself (|L|^2 = 2 E I_mid exactly, k = 1, an infinitely long
//     period) is excluded: the constructor throws std::domain_error within a relative distance
//     of 1e-12 of it.
#include "physics/math.h"

#include <cstdint>

namespace tumble::exact {

using physics::Mat3;
using physics::Quat;
using physics::Vec3;

struct RotationState {
    Quat q; // orientation of the mass frame, body -> world (unit)
    Vec3 w; // angular velocity, world, rad/s
};

class ExactFreeRigidBody {
  public:
    enum class Regime : std::uint8_t {
        Isotropic,
        Axisymmetric,
        PrincipalSpin,
        AroundLargestAxis,
        AroundSmallestAxis,
    };

    // inertia: principal moments (I1, I2, I3) > 0, kg m^2; q0: mass frame at t = 0 (normalised
    // here); w0: world angular velocity at t = 0. Throws std::domain_error on the separatrix and
    // std::invalid_argument for non-positive moments or non-finite input.
    ExactFreeRigidBody(const Vec3& inertia, const Quat& q0, const Vec3& w0);

    RotationState state_at(double t) const;
    Vec3 body_momentum_at(double t) const; // m(t), mass frame

    Vec3 angular_momentum() const { return L_world_; } // world, constant
    double energy() const { return energy_; }          // 1/2 w . I_w w, constant
    Regime regime() const { return regime_; }
    double modulus() const { return k_; } // k of sn, cn, dn (0 outside the Jacobi regimes)
    // Period of m(t) in the body frame (4 K / |nu| for the Jacobi regimes, 2 pi / |lambda| for
    // regular precession; infinity when m is constant).
    double body_period() const;

  private:
    Vec3 jacobi_body_momentum(double u) const; // (p, q, r) frame, see the .cpp
    RotationState jacobi_state(double t) const;
    RotationState precession_state(double t) const;

    Vec3 inertia_;
    Quat q0_;
    Vec3 m0_;      // body momentum at t = 0, mass frame
    Vec3 L_world_; // world angular momentum
    double energy_ = 0.0;
    Regime regime_ = Regime::Isotropic;

    // Regular precession: R(t) = exp(t L / I_t) R0 exp(lambda t e_s).
    int axis_s_ = 2;
    double I_t_ = 1.0;
    double lambda_ = 0.0;

    // Jacobi regimes, in the (p, q, r) frame: r is the axis the body turns around (largest moment
    // if |L|^2 > 2 E I_mid, smallest otherwise), q the middle one. m_mass = P m_pqr.
    Mat3 P_ = Mat3::Identity();
    Vec3 I_pqr_ = Vec3::Ones();
    double alpha_ = 0.0, beta_ = 0.0, gamma_ = 0.0;  // m = (alpha cn u, beta sn u, gamma dn u)
    double k_ = 0.0, nu_ = 0.0, u0_ = 0.0;           // u = u0 + nu t
    double K_ = 0.0;                                 // complete elliptic integral K(k)
    double n_ = 0.0, Pi_complete_ = 0.0, Pi0_ = 0.0; // characteristic, Pi(n, k), Pi(n; am u0, k)
    double phi_rate_ = 0.0, phi_pi_ = 0.0; // phi(t) = phi_rate t + phi_pi (Pi(am u) - Pi0)
    Mat3 W_ = Mat3::Identity();            // invariant frame: W e_z = L / |L|
    double L_norm_ = 0.0;
};

const char* regime_name(ExactFreeRigidBody::Regime regime);

} // namespace tumble::exact
