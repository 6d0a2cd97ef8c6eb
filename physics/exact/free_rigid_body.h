#pragma once
// The exact motion of a torque-free rigid body (Euler 1758, Jacobi 1849), as an oracle for tests,
// benchmarks and `tumble study`. The computation is physics::FreeRotation (physics/
// free_rotation.h), the same code the `exact` and `splitting_exact` integrators step with: the
// oracle adds the checks of its input and refuses the separatrix. So it is tested on its own terms
// (tests/physics/exact_free_body_test.cpp: Euler's equations and dq/dt = 1/2 (0, w) (x) q by finite
// differences, energy and world angular momentum, a very fine Runge-Kutta integration written in
// the test), and the integrators that share it are tested against references written in their own
// tests (tests/physics/exact_integrator_test.cpp), never against this oracle.
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
//     period) is excluded from the oracle: its constructor throws std::domain_error within a
//     relative distance of 1e-12 of it, where the flips' timing depends on the last bits of the
//     state and no reference can be trusted (the integrators do step there: free_rotation.h).
#include "physics/free_rotation.h"
#include "physics/math.h"

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
    using Regime = physics::FreeRegime;

    // inertia: principal moments (I1, I2, I3) > 0, kg m^2; q0: mass frame at t = 0 (normalised
    // here); w0: world angular velocity at t = 0. Throws std::domain_error on the separatrix and
    // std::invalid_argument for non-positive moments or non-finite input.
    ExactFreeRigidBody(const Vec3& inertia, const Quat& q0, const Vec3& w0);

    RotationState state_at(double t) const;
    Vec3 body_momentum_at(double t) const { return motion_.body_momentum_at(t); } // mass frame

    Vec3 angular_momentum() const { return motion_.angular_momentum(); } // world, constant
    double energy() const { return motion_.energy(); }                   // 1/2 w . I_w w, constant
    Regime regime() const { return motion_.regime(); }
    double modulus() const { return motion_.modulus(); } // k of sn, cn, dn (0 outside Jacobi)
    // Period of m(t) in the body frame (4 K / |nu| for the Jacobi regimes, 2 pi / |lambda| for
    // regular precession; infinity when m is constant).
    double body_period() const { return motion_.body_period(); }

  private:
    physics::FreeRotation motion_;
};

const char* regime_name(ExactFreeRigidBody::Regime regime);

} // namespace tumble::exact
