// Stability at the extremes (issue 6): each test pins the qualitative behaviour of the integrators
// in one corner of the input space, with the measured values printed beside the bounds.
//   tiny steps        h = 1e-7 over 1e6 steps: the error keeps following the method's truncation
//                     law down to a round-off floor; the position is summed with Kahan's
//                     compensation (physics/compensated.h), so its increments are not lost even
//                     1e6 m from the origin
//   far from origin   1e6 m: the rotation is bit-identical to the same run at the origin, the
//                     displacement equal to the round-off of a 1e6 m coordinate
//   very fast spin    |w| = 1e4 rad/s
//   near-degenerate   I1 = I2 (1 + 1e-12): the same motion as the exact symmetric top
//   long runs         1e7 steps of `splitting`: energy error bounded, no drift
// (Extreme mass ratios need contacts: tests/physics/contact_*_test.cpp once they land.)
#include "integrator_harness.h"

#include "physics/diagnostics.h"

#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tumble::physics {
namespace {

using testing::all_integrators;
using testing::make_world;
using testing::name_of;
using testing::World;

struct Measured {
    double orientation = 0.0; // rad
    double position = 0.0;    // m
};

// Runs `steps` steps and measures body 0 against its exact motion.
Measured run_against_exact(const scenes::Scene& scene, Integrator id, double h, long steps) {
    World w = make_world(scene, id, h);
    const exact::ExactBodyMotion ex(w.model, w.state, 0);
    testing::run(w, steps);
    const exact::BodyState b = ex.at(w.state.time(w.model));
    return {rotation_angle_between(w.state.q[0], b.q), (w.state.x[0] - b.x).norm()};
}

scenes::Scene moving_flip() {
    scenes::Scene s = scenes::intermediate_axis_scene();
    s.bodies[0].position = Vec3(1.0, 2.0, 3.0);
    s.bodies[0].velocity = Vec3(0.3, -0.2, 0.1);
    return s;
}

TEST(Extremes, TinyStepsFollowTheTruncationLawDownToRoundOff) {
    // t = 0.1 s of the intermediate-axis book (|w| = 6 rad/s) moving at 0.37 m/s, at h = 1e-5 and
    // at h = 1e-7 (1e6 steps). Between the two the truncation error shrinks by 100^p; the error
    // at 1e-7 must be that prediction or a round-off floor of 1e-10 rad (1e6 steps times the
    // double epsilon: rotation round-off grows at most linearly), not more. Time is never
    // accumulated (t = step * dt, state.h) and the position is summed with Kahan's compensation
    // (physics/compensated.h); the rotation is renormalised each step but not compensated:
    // measured 1e-12 (rk4, splitting, midpoint) to 2.5e-11 rad (splitting4, 5 stages a step).
    // The exact-flow methods truncate nothing (p = 0 predicts no change) and round differently:
    // each free flow recomputes the elliptic phase of the state, rounded at the scale of K (~6
    // here) rather than of the step's small turn, ~1e-15 rad a flow in a random walk. Their floor
    // is 5e-10: measured 6.5e-11 (exact, splitting_exact) and 2.9e-10 (splitting4_exact, 5e6
    // flows); 1.8e-12 and 2.0e-12 rad at h = 1e-5 s (1e4 steps).
    const scenes::Scene scene = moving_flip();
    for (Integrator id : all_integrators()) {
        const int p = integrator_info(id).order;
        const Measured coarse = run_against_exact(scene, id, 1e-5, 10000);
        const Measured tiny = run_against_exact(scene, id, 1e-7, 1000000);
        const double predicted = coarse.orientation * std::pow(1e-2, p);
        const double floor = integrator_info(id).exact_without_torque ? 5e-10 : 1e-10;
        const double bound = 2.0 * predicted + floor;
        std::printf("%s: h=1e-5 %.3g rad, h=1e-7 %.3g rad (predicted %.3g), position %.3g m\n",
                    name_of(id).c_str(), coarse.orientation, tiny.orientation, predicted,
                    tiny.position);
        TUMBLE_MEASURED(tiny.orientation, bound);
        EXPECT_LE(tiny.orientation, bound) << name_of(id);
        // Translation at constant velocity is exact per step, so this is all round-off: Kahan-
        // compensated (physics/compensated.h), about one ulp of |x| = 3.2 m (4.4e-16 m).
        TUMBLE_MEASURED(tiny.position, 4e-15);
        EXPECT_LE(tiny.position, 4e-15) << name_of(id);
    }
}

TEST(Extremes, FarFromTheOriginTheRotationIsUntouched) {
    // The flip thrown under gravity, at the origin and 1.7e6 m away: rotation does not depend on
    // where the body is, so q and w must be bit-identical; the displacement x(t) - x(0) must be the
    // same to the round-off of a 1e6 m coordinate (ulp = 1.2e-10 m), whatever the method's own
    // truncation error.
    scenes::Scene near = scenes::intermediate_axis_scene(), far = near;
    near.world.gravity = far.world.gravity = Vec3(0.0, 0.0, -9.81);
    near.bodies[0].velocity = far.bodies[0].velocity = Vec3(0.5, -0.5, 5.0);
    far.bodies[0].position = Vec3(1e6, -1e6, 1e6);
    for (Integrator id : all_integrators()) {
        World a = make_world(near, id, 1.0 / 240.0), b = make_world(far, id, 1.0 / 240.0);
        const Vec3 a0 = a.state.x[0], b0 = b.state.x[0];
        testing::run(a, 480);
        testing::run(b, 480);
        EXPECT_TRUE(a.state.q[0].coeffs() == b.state.q[0].coeffs() && a.state.w[0] == b.state.w[0])
            << name_of(id);
        const double displacement = ((b.state.x[0] - b0) - (a.state.x[0] - a0)).norm();
        TUMBLE_MEASURED(displacement, 5e-10);
        EXPECT_LE(displacement, 5e-10) << name_of(id);
    }
}

TEST(Extremes, TinyStepsFarFromTheOriginKeepTheirIncrements) {
    // h = 1e-7 s at 1e6 m: each increment h v (3e-8 m) is 260 ulps of x, so a naive x += h v
    // rounds away up to 0.2% of every step. Compensated summation (compensated.h) keeps them.
    scenes::Scene s = moving_flip();
    s.bodies[0].position = Vec3(1e6, -1e6, 1e6);
    const Integrator id = integrator_from_name("splitting").value();
    World w = make_world(s, id, 1e-7);
    const Vec3 x0 = w.state.x[0], v = w.state.v[0];
    Vec3 naive = x0;
    for (long k = 0; k < 1000000; ++k) naive += 1e-7 * v; // what x += h v alone would give
    testing::run(w, 1000000);
    const Vec3 exact = x0 + 0.1 * v;
    const double compensated_error = (w.state.x[0] - exact).norm();
    const double naive_error = (naive - exact).norm();
    TUMBLE_MEASURED(naive_error, 1e-6);
    TUMBLE_MEASURED(compensated_error, 5e-10);
    EXPECT_GT(naive_error, 1e-6); // the failure compensated summation is there for
    EXPECT_LE(compensated_error, 5e-10);
}

TEST(Extremes, VeryFastSpinIsTheSlowSpinInFastTime) {
    // Torque-free motion scales exactly: w -> s w, t -> t / s. At |w| = 1e4 rad/s and h = 1e-6 s
    // every integrator must do what it does at |w| = 1 rad/s and h = 1e-2 s (same h|w| = 0.01):
    // no absolute tolerance, threshold or clamp inside may depend on the spin rate.
    scenes::Scene slow = scenes::tumbling_box_scene(), fast = slow;
    const Vec3 dir = Vec3(1.0, 2.0, 3.0).normalized();
    slow.bodies[0].angular_velocity = dir;
    fast.bodies[0].angular_velocity = 1e4 * dir;
    for (Integrator id : all_integrators()) {
        World a = make_world(slow, id, 1e-2), b = make_world(fast, id, 1e-6);
        testing::run(a, 1000);
        testing::run(b, 1000);
        const double angle = rotation_angle_between(a.state.q[0], b.state.q[0]);
        const double rate = (1e-4 * b.state.w[0] - a.state.w[0]).norm();
        TUMBLE_MEASURED(angle, 1e-10);
        TUMBLE_MEASURED(rate, 1e-10);
        EXPECT_LE(angle, 1e-10) << name_of(id);
        EXPECT_LE(rate, 1e-10) << name_of(id);
    }
}

TEST(Extremes, VeryFastSpinAtAnOrdinaryStep) {
    // |w| = 1e4 rad/s at the default h = 1/240 s: h|w| = 42, a turn of 6.6 revolutions a step.
    // The methods built from exact rotations keep |L| and world L to round-off and do not blow
    // up; the accuracy is gone, but nothing becomes NaN.
    scenes::Scene s = scenes::tumbling_box_scene();
    s.bodies[0].angular_velocity = 1e4 * Vec3(1.0, 2.0, 3.0).normalized();
    for (const char* name : {"splitting", "splitting4"}) {
        World w = make_world(s, integrator_from_name(name).value(), 1.0 / 240.0);
        const Diagnostics d0 = diagnose(w.model, w.state);
        testing::run(w, 2400);
        const Diagnostics d = diagnose(w.model, w.state);
        const double momentum =
            (d.angular_momentum - d0.angular_momentum).norm() / d0.angular_momentum.norm();
        const double energy = std::abs(d.energy() - d0.energy()) / d0.energy();
        std::printf("%s: ", name);
        TUMBLE_MEASURED(momentum, 1e-12);
        TUMBLE_MEASURED(energy, 0.5);
        EXPECT_LE(momentum, 1e-12) << name;
        EXPECT_LE(energy, 0.5) << name;
    }
}

TEST(Extremes, NearlyDegenerateInertiaIsTheSymmetricTop) {
    // I1 = I2 (1 + 1e-12): the motion must be that of the exact symmetric top I1 = I2 to within
    // what 1e-12 of inertia can change over the run, for the integrators and for the oracle (which
    // takes its Jacobi branch for the one and its precession branch for the other).
    const Vec3 sym(0.02, 0.02, 0.01), near(0.02, 0.02 * (1.0 + 1e-12), 0.01);
    const Vec3 w0(1.0, 0.5, 6.0);
    for (Integrator id : all_integrators()) {
        scenes::Scene a = scenes::tumbling_box_scene(), b = a;
        a.bodies[0].inertia = sym.asDiagonal();
        b.bodies[0].inertia = near.asDiagonal();
        a.bodies[0].angular_velocity = b.bodies[0].angular_velocity = w0;
        World wa = make_world(a, id, 0.005), wb = make_world(b, id, 0.005);
        testing::run(wa, 1000);
        testing::run(wb, 1000);
        const double angle = rotation_angle_between(wa.state.q[0], wb.state.q[0]);
        TUMBLE_MEASURED(angle, 1e-10);
        EXPECT_LE(angle, 1e-10) << name_of(id);
    }
    const exact::ExactFreeRigidBody ea(sym, Quat::Identity(), w0), eb(near, Quat::Identity(), w0);
    double oracle = 0.0;
    for (double t : {0.1, 1.0, 5.0})
        oracle = std::max(oracle, rotation_angle_between(ea.state_at(t).q, eb.state_at(t).q));
    std::printf("oracle regimes: %s / %s\n", exact::regime_name(ea.regime()),
                exact::regime_name(eb.regime()));
    TUMBLE_MEASURED(oracle, 1e-10);
    EXPECT_LE(oracle, 1e-10);
}

TEST(Extremes, TenMillionSplittingStepsKeepEnergyBounded) {
    // MuJoCo's tumbling box at h = 0.01 s (h|w| = 0.037) for 1e7 steps (1e5 s, ~1e5 tumbles):
    // a symplectic method's energy error oscillates without drift, so the worst error of the last
    // tenth is no larger than that of the first tenth (up to the oscillation's sampling), and
    // world L is kept to round-off.
    const scenes::Scene s = scenes::tumbling_box_scene();
    World w = make_world(s, integrator_from_name("splitting").value(), 0.01);
    const Diagnostics d0 = diagnose(w.model, w.state);
    const long steps = 10000000, every = 1000;
    double first = 0.0, last = 0.0, worst = 0.0;
    for (long k = 1; k <= steps; ++k) {
        step(w.model, w.state);
        if (k % every != 0) continue;
        const double e = std::abs(diagnose(w.model, w.state).energy() - d0.energy()) / d0.energy();
        worst = std::max(worst, e);
        if (k <= steps / 10) first = std::max(first, e);
        if (k > steps - steps / 10) last = std::max(last, e);
    }
    const double momentum =
        (diagnose(w.model, w.state).angular_momentum - d0.angular_momentum).norm() /
        d0.angular_momentum.norm();
    TUMBLE_MEASURED(first, 1e-3);
    TUMBLE_MEASURED(last, 1.1 * first);
    TUMBLE_MEASURED(worst, 1e-3);
    TUMBLE_MEASURED(momentum, 1e-10);
    EXPECT_LE(last, 1.1 * first);
    EXPECT_LE(worst, 1e-3);
    EXPECT_LE(momentum, 1e-10);
}

} // namespace
} // namespace tumble::physics
