// The oracles are tested on their own before anything is measured against them: the torque-free
// body must satisfy Euler's equations and the kinematics dR/dt = [w]x R by finite differences,
// keep its energy and world angular momentum, and agree with a very fine Runge-Kutta integration
// written here, independently of the physics integrators.
#include "physics/exact/body_motion.h"
#include "physics/exact/free_rigid_body.h"
#include "physics/exact/simple_motions.h"

#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace tumble::exact {
namespace {

const Quat kQ0 = Quat(Eigen::AngleAxisd(0.7, Vec3(0.3, -1.0, 0.6).normalized()));

using Regime = ExactFreeRigidBody::Regime;

struct Case {
    std::string name;
    Vec3 inertia;
    Vec3 w_body; // initial angular velocity in the mass frame
    Regime regime;
    Quat q0 = Quat(Eigen::AngleAxisd(0.7, Vec3(0.3, -1.0, 0.6).normalized()));
};

// Every regime, with axis orders that need an odd permutation to reach (p, q, r).
std::vector<Case> cases() {
    return {
        {"largest", Vec3(1.0, 2.0, 3.0), Vec3(0.3, 0.2, 4.0), Regime::AroundLargestAxis},
        {"smallest", Vec3(1.0, 2.0, 3.0), Vec3(4.0, 0.2, 0.3), Regime::AroundSmallestAxis},
        {"flip_largest", Vec3(1.0, 2.0, 3.0), Vec3(0.02, 3.0, 0.02), Regime::AroundLargestAxis},
        {"flip_smallest", Vec3(1.0, 2.0, 3.0), Vec3(0.05, 3.0, 0.01), Regime::AroundSmallestAxis},
        {"permuted_odd", Vec3(0.3, 0.1, 0.2), Vec3(1.5, 0.4, -2.0), Regime::AroundLargestAxis},
        {"book_flip", Vec3(6.1667e-3, 9.2267e-3, 3.3933e-3), Vec3(6.0, 0.05, 0.05),
         Regime::AroundLargestAxis},
        {"axisymmetric", Vec3(1.0, 1.0, 2.5), Vec3(0.5, -1.0, 3.0), Regime::Axisymmetric},
        {"axisymmetric_x", Vec3(2.0, 1.0, 1.0), Vec3(0.5, -1.0, 3.0), Regime::Axisymmetric},
        {"isotropic", Vec3(0.7, 0.7, 0.7), Vec3(0.5, -1.0, 3.0), Regime::Isotropic},
        // Exactly along a principal axis only with exact zeros: identity orientation.
        {"middle_axis_spin", Vec3(1.0, 2.0, 3.0), Vec3(0.0, 3.0, 0.0), Regime::PrincipalSpin,
         Quat::Identity()},
    };
}

ExactFreeRigidBody make(const Case& c) {
    return ExactFreeRigidBody(c.inertia, c.q0, c.q0 * c.w_body);
}

const double kTimes[] = {0.0, 0.37, 1.9, 6.3, 17.5, 41.0};

TEST(ExactFreeRigidBody, DetectsTheRegime) {
    for (const Case& c : cases()) {
        const ExactFreeRigidBody body = make(c);
        EXPECT_EQ(body.regime(), c.regime) << c.name << ": " << regime_name(body.regime());
    }
}

TEST(ExactFreeRigidBody, StartsFromTheGivenState) {
    double worst = 0.0;
    for (const Case& c : cases()) {
        const RotationState s = make(c).state_at(0.0);
        worst = std::max({worst, physics::rotation_angle_between(s.q, c.q0),
                          (s.w - c.q0 * c.w_body).norm() / c.w_body.norm()});
    }
    TUMBLE_MEASURED(worst, 1e-14);
    EXPECT_LT(worst, 1e-14);
}

// Sixth-order central difference of f at t with step d.
template <class F>
auto derivative(const F& f, double t, double d) {
    using Value = decltype(f(t)); // a plain Eigen matrix, never an expression of temporaries
    return Value((45.0 * (f(t + d) - f(t - d)) - 9.0 * (f(t + 2 * d) - f(t - 2 * d)) +
                  (f(t + 3 * d) - f(t - 3 * d))) /
                 (60.0 * d));
}

TEST(ExactFreeRigidBody, SatisfiesEulersEquationsByFiniteDifferences) {
    // dm/dt = m x w_body (Euler's equations in the body frame, torque-free), and
    // dR/dt = [w]x R (the kinematics, world w): both to near round-off.
    double worst_euler = 0.0, worst_kin = 0.0;
    for (const Case& c : cases()) {
        const ExactFreeRigidBody body = make(c);
        const double d = 2e-3 / c.w_body.norm();
        const auto m_at = [&](double t) { return body.body_momentum_at(t); };
        const auto R_at = [&](double t) { return Mat3(body.state_at(t).q.toRotationMatrix()); };
        for (double t : kTimes) {
            const Vec3 m = m_at(t);
            const Vec3 rhs = m.cross(m.cwiseQuotient(c.inertia));
            const double scale = m.norm() * m.cwiseQuotient(c.inertia).norm();
            worst_euler = std::max(worst_euler, (derivative(m_at, t, d) - rhs).norm() / scale);
            const RotationState s = body.state_at(t);
            const Mat3 dR = physics::skew(s.w) * s.q.toRotationMatrix();
            const double err = (derivative(R_at, t, d) - dR).norm() / s.w.norm();
            worst_kin = std::max(worst_kin, err);
            EXPECT_LT(err, 2e-10) << c.name << " t = " << t;
        }
    }
    TUMBLE_MEASURED(worst_euler, 1e-10);
    TUMBLE_MEASURED(worst_kin, 2e-10);
    EXPECT_LT(worst_euler, 1e-10);
}

TEST(ExactFreeRigidBody, KeepsEnergyAndWorldAngularMomentum) {
    double worst_e = 0.0, worst_l = 0.0;
    for (const Case& c : cases()) {
        const ExactFreeRigidBody body = make(c);
        for (int j = 0; j <= 200; ++j) {
            const RotationState s = body.state_at(0.5 * j);
            const Vec3 wb = s.q.conjugate() * s.w;
            const Vec3 L = s.q * c.inertia.cwiseProduct(wb);
            const double E = 0.5 * wb.dot(c.inertia.cwiseProduct(wb));
            worst_e = std::max(worst_e, std::abs(E / body.energy() - 1.0));
            worst_l = std::max(worst_l, (L - body.angular_momentum()).norm() /
                                            body.angular_momentum().norm());
        }
    }
    TUMBLE_MEASURED(worst_e, 1e-13);
    TUMBLE_MEASURED(worst_l, 1e-13);
    EXPECT_LT(worst_e, 1e-13);
    EXPECT_LT(worst_l, 1e-13);
}

// Classic RK4 on (m, q) in the body frame, independent of physics/integrator_*:
//   dm/dt = m x I^-1 m,   dq/dt = 1/2 q (x) (0, I^-1 m).
struct BodyRk4 {
    Vec3 I;
    Vec3 m;
    Quat q;

    void step(double h) {
        struct D {
            Vec3 dm;
            Eigen::Vector4d dq;
        };
        const auto f = [&](const Vec3& mm, const Eigen::Vector4d& qq) {
            const Vec3 w = mm.cwiseQuotient(I);
            const Quat qd = Quat(qq) * Quat(0.0, w.x(), w.y(), w.z());
            return D{mm.cross(w), 0.5 * qd.coeffs()};
        };
        const Eigen::Vector4d q0 = q.coeffs();
        const D k1 = f(m, q0);
        const D k2 = f(m + 0.5 * h * k1.dm, q0 + 0.5 * h * k1.dq);
        const D k3 = f(m + 0.5 * h * k2.dm, q0 + 0.5 * h * k2.dq);
        const D k4 = f(m + h * k3.dm, q0 + h * k3.dq);
        m += h / 6.0 * (k1.dm + 2.0 * k2.dm + 2.0 * k3.dm + k4.dm);
        q = Quat(Eigen::Vector4d(q0 + h / 6.0 * (k1.dq + 2.0 * k2.dq + 2.0 * k3.dq + k4.dq)));
        q.normalize();
    }
};

TEST(ExactFreeRigidBody, OrientationAgreesWithVeryFineRungeKutta) {
    // RK4 at h |w| = 3e-4 over 6 s: its own error is ~1e-11 rad, below the bound (measured worst
    // difference 4e-11 rad).
    double worst = 0.0;
    for (const Case& c : cases()) {
        const ExactFreeRigidBody body = make(c);
        BodyRk4 rk{c.inertia, c.inertia.cwiseProduct(c.w_body), c.q0};
        const double h = 3e-4 / c.w_body.norm();
        const int steps_per_check = static_cast<int>(std::ceil(2.0 / h));
        const double hh = 2.0 / steps_per_check;
        for (int check = 1; check <= 3; ++check) {
            for (int k = 0; k < steps_per_check; ++k) rk.step(hh);
            const RotationState s = body.state_at(2.0 * check);
            const double err = physics::rotation_angle_between(rk.q, s.q);
            worst = std::max(worst, err);
            EXPECT_LT(err, 1e-9) << c.name << " t = " << 2.0 * check;
        }
    }
    TUMBLE_MEASURED(worst, 1e-9);
}

TEST(ExactFreeRigidBody, RefusesTheSeparatrix) {
    // 2 E I_mid = |L|^2: m on the separatrix through the middle axis, here m = (a, 2 b, c) with
    // a^2 (1 - 2/1) + c^2 (1 - 2/3) = 0.
    const Vec3 I(1.0, 2.0, 3.0);
    const double c = 1.0, a = std::sqrt(1.0 / 3.0);
    EXPECT_THROW(ExactFreeRigidBody(I, Quat::Identity(), Vec3(a / 1.0, 0.5, c / 3.0)),
                 std::domain_error);
}

TEST(ExactFreeRigidBody, NearlySymmetricBodyApproachesTheSymmetricTop) {
    // The Jacobi solution for I = (1, 1 + e, 2.5) tends to the trigonometric one for (1, 1, 2.5)
    // as e -> 0: the error of the limit shrinks in proportion to e.
    const Vec3 w(0.5, -1.0, 3.0);
    const ExactFreeRigidBody top(Vec3(1.0, 1.0, 2.5), kQ0, kQ0 * w);
    double prev = 0.0;
    for (double e : {1e-3, 1e-4}) {
        const ExactFreeRigidBody near(Vec3(1.0, 1.0 + e, 2.5), kQ0, kQ0 * w);
        ASSERT_EQ(near.regime(), Regime::AroundLargestAxis);
        const double diff =
            physics::rotation_angle_between(near.state_at(3.0).q, top.state_at(3.0).q);
        TUMBLE_MEASURED(diff, 10.0 * e);
        EXPECT_LT(diff, 10.0 * e);
        if (prev > 0.0) {
            EXPECT_NEAR(prev / diff, 10.0, 1.0);
        }
        prev = diff;
    }
}

TEST(ConstantTorqueSphere, SatisfiesNewtonEulerByFiniteDifferences) {
    const double I = 0.02;
    const Vec3 w0(1.0, -2.0, 2.0), tau = 0.03 * w0.normalized();
    const ConstantTorqueSphere sphere(I, kQ0, w0, tau);
    const auto w_at = [&](double t) { return sphere.state_at(t).w; };
    const auto R_at = [&](double t) { return Mat3(sphere.state_at(t).q.toRotationMatrix()); };
    const double t = 1.3, d = 1e-3;
    const double err_w = (derivative(w_at, t, d) - tau / I).norm() / (tau / I).norm();
    const RotationState s = sphere.state_at(t);
    const double err_r =
        (derivative(R_at, t, d) - physics::skew(s.w) * s.q.toRotationMatrix()).norm() / s.w.norm();
    TUMBLE_MEASURED(err_w, 1e-9);
    TUMBLE_MEASURED(err_r, 1e-9);
    EXPECT_LT(err_w, 1e-9);
    EXPECT_LT(err_r, 1e-9);
    EXPECT_THROW(ConstantTorqueSphere(I, kQ0, w0, Vec3(0.0, 0.0, 0.01)), std::domain_error);
}

TEST(Projectile, SatisfiesNewtonByFiniteDifferences) {
    const Projectile p{Vec3(1.0, 2.0, 3.0), Vec3(0.5, -1.0, 4.0), Vec3(0.0, 0.0, -9.81)};
    const auto x_at = [&](double t) { return p.x_at(t); };
    const auto v_at = [&](double t) { return p.v_at(t); };
    const double err = (derivative(x_at, 0.8, 1e-2) - p.v_at(0.8)).norm() +
                       (derivative(v_at, 0.8, 1e-2) - p.a).norm();
    TUMBLE_MEASURED(err, 1e-12);
    EXPECT_LT(err, 1e-12);
}

} // namespace
} // namespace tumble::exact
