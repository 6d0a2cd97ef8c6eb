// What each integrator conserves, and how the explicit ones fail, on torque-free tumbling:
//   splitting, midpoint: world angular momentum to 1e-12 over 100000 steps; energy error that
//     does not grow (first tenth of the run against the last tenth).
//   symplectic_euler (MuJoCo's Euler): gains energy on MuJoCo's tumbling box, every step.
//   euler, the course loop in the world frame: loses energy and |L| on the same box (not gains:
//     see integrator_euler.cpp for why the sign differs from the body-frame explicit Euler).
//   implicit_gyro: never gains energy, checked step by step.
//   euler_momentum: world angular momentum exact (to round-off) although the energy drifts.
#include "integrator_harness.h"

#include "physics/diagnostics.h"

#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tumble::physics {
namespace {

using testing::make_world;
using testing::name_of;
using testing::World;

double rel(const Vec3& a, const Vec3& b) {
    return (a - b).norm() / b.norm();
}

struct LongRun {
    double worst_l = 0.0;      // max |L - L0| / |L0| over the run
    double energy_first = 0.0; // max |E / E0 - 1| over the first tenth
    double energy_last = 0.0;  // ... and over the last tenth
};

LongRun long_run(Integrator integrator, long steps) {
    World w = make_world(scenes::intermediate_axis_scene(), integrator, 1.0 / 240.0);
    const Diagnostics d0 = diagnose(w.model, w.state);
    LongRun r;
    for (long k = 1; k <= steps; ++k) {
        step(w.model, w.state);
        const Diagnostics d = diagnose(w.model, w.state);
        r.worst_l = std::max(r.worst_l, rel(d.angular_momentum, d0.angular_momentum));
        const double de = std::abs(d.energy() / d0.energy() - 1.0);
        if (k <= steps / 10) r.energy_first = std::max(r.energy_first, de);
        if (k > steps - steps / 10) r.energy_last = std::max(r.energy_last, de);
    }
    return r;
}

// 100000 steps of 1/240 s: 417 s of the book flipping back and forth (112 flips).
LongRun expect_geometric(Integrator integrator) {
    const LongRun r = long_run(integrator, 100000);
    std::printf("[measured] %s: |dL|/|L| max %.3g, |dE|/E max first tenth %.3g, last tenth %.3g\n",
                name_of(integrator).c_str(), r.worst_l, r.energy_first, r.energy_last);
    TUMBLE_MEASURED(r.worst_l, 1e-12);
    EXPECT_LT(r.worst_l, 1e-12);
    // "Does not grow": the last tenth stays within 1.5 times the first tenth, plus a floor of
    // 1e-13 for the round-off random walk of 1e5 steps (~sqrt(1e5) * 1e-16 ~ 3e-14).
    const double bound = 1.5 * r.energy_first + 1e-13;
    TUMBLE_MEASURED(r.energy_last, bound);
    EXPECT_LT(r.energy_last, bound);
    return r;
}

TEST(Conservation, SplittingKeepsAngularMomentumAndBoundedEnergy) {
    const LongRun r = expect_geometric(Integrator::Splitting);
    // The bounded-energy claim is not vacuous for splitting: its energy error is O(h^2), far
    // above round-off, and still does not grow.
    TUMBLE_MEASURED(r.energy_first, 1e-9);
    EXPECT_GT(r.energy_first, 1e-9);
}

TEST(Conservation, MidpointKeepsAngularMomentumAndEnergy) {
    expect_geometric(Integrator::Midpoint);
}

// MuJoCo's box: half sizes (0.1, 0.2, 0.3), 1 kg, w0 = (1, 2, 3), h = 0.01, 500 steps (5 s).
double energy_ratio_after_5s(Integrator integrator) {
    World w = make_world(scenes::tumbling_box_scene(), integrator, 0.01);
    const double e0 = diagnose(w.model, w.state).energy();
    testing::run(w, 500);
    return diagnose(w.model, w.state).energy() / e0;
}

TEST(Conservation, EulerDriftsEnergyOnTheTumblingBoxAndLosesIt) {
    // The course loop rotates R with the old w while w moves: to leading order the energy falls by
    // h^2 g . I^-1 g per step (integrator_euler.cpp). Measured: E(5 s) / E0 = 0.847 at h = 0.01,
    // 0.979 at h = 0.001 (first order). The issue expected a gain, which is what the body-frame
    // explicit Euler and symplectic_euler do (next test); the world-frame loop loses.
    const double ratio = energy_ratio_after_5s(Integrator::Euler);
    TUMBLE_MEASURED(ratio, 0.95);
    EXPECT_LT(ratio, 0.95); // a clear loss, not round-off
}

TEST(Conservation, SymplecticEulerGainsEnergyEveryStep) {
    // Torque-free, the step is exactly w_b' = w_b + h I^-1 (m x w_b) in the body frame, so
    // 2 E' = 2 E + h^2 |m x w_b|^2_{I^-1} > 2 E at every step (integrator_symplectic_euler.cpp).
    World w = make_world(scenes::tumbling_box_scene(), Integrator::SymplecticEuler, 0.01);
    const double e0 = diagnose(w.model, w.state).energy();
    double prev = e0;
    int decreases = 0;
    for (int k = 0; k < 500; ++k) {
        step(w.model, w.state);
        const double e = diagnose(w.model, w.state).energy();
        decreases += e <= prev;
        prev = e;
    }
    const double ratio = prev / e0; // MuJoCo measures 1.09 for its Euler on this box
    TUMBLE_MEASURED(ratio, 1.05);
    TUMBLE_MEASURED(decreases, 0);
    EXPECT_GT(ratio, 1.05);
    EXPECT_EQ(decreases, 0);
}

TEST(Conservation, ImplicitGyroNeverGainsEnergy) {
    // Per-step check: E_{n+1} <= E_n, to the round-off of evaluating the energy (4 ulps). The
    // derivation in integrator_implicit_gyro.cpp proves it while h |w| <= I_min / (I_max - I_min);
    // the two scenes below satisfy that (checked), and the run must dissipate visibly (so the
    // check is not passed by a method that does nothing).
    for (const scenes::Scene& scene :
         {scenes::tumbling_box_scene(), scenes::intermediate_axis_scene()}) {
        const double h = 0.01;
        World w = make_world(scene, Integrator::ImplicitGyro, h);
        const Vec3& I = w.model.inertia[0];
        const double bound = I.minCoeff() / (I.maxCoeff() - I.minCoeff());
        ASSERT_LE(h * w.state.w[0].norm(), bound) << scene.name;
        const double e0 = diagnose(w.model, w.state).energy();
        double prev = e0, worst_gain = -1.0;
        for (int k = 0; k < 2000; ++k) {
            step(w.model, w.state);
            const double e = diagnose(w.model, w.state).energy();
            worst_gain = std::max(worst_gain, (e - prev) / prev);
            prev = e;
        }
        const double lost = 1.0 - prev / e0;
        std::printf("[measured] %s: worst per-step relative gain %.3g, energy lost in 20 s %.3g\n",
                    scene.name.c_str(), worst_gain, lost);
        TUMBLE_MEASURED(worst_gain, 4.4e-16);
        EXPECT_LE(worst_gain, 4.4e-16) << scene.name;
        EXPECT_GT(lost, 1e-4) << scene.name;
    }
}

TEST(Conservation, EulerMomentumKeepsWorldAngularMomentumButNotEnergy) {
    World w = make_world(scenes::tumbling_box_scene(), Integrator::EulerMomentum, 0.01);
    const Diagnostics d0 = diagnose(w.model, w.state);
    testing::run(w, 500);
    const Diagnostics d = diagnose(w.model, w.state);
    const double dl = rel(d.angular_momentum, d0.angular_momentum);
    const double de = std::abs(d.energy() / d0.energy() - 1.0);
    TUMBLE_MEASURED(dl, 1e-13);
    TUMBLE_MEASURED(de, 1e-3);
    EXPECT_LT(dl, 1e-13);
    EXPECT_GT(de, 1e-3); // the error is all in the orientation, and the energy shows it
}

} // namespace
} // namespace tumble::physics
