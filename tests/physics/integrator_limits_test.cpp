// How the integrators behave far beyond their accuracy range (h |w| = 50, the Divergence test's
// spinning box): the implicit gyroscopic step stays finite and bounded, and the
// implicit midpoint fails loudly when its Newton solve cannot converge, instead of going on with
// an unconverged rotation.
#include "integrator_harness.h"

#include "physics/diagnostics.h"

#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace tumble::physics {
namespace {

using testing::make_world;
using testing::World;

scenes::Scene fast_spin() {
    scenes::Scene scene = scenes::tumbling_box_scene();
    scene.bodies[0].angular_velocity = Vec3(0.1, 100.0, 0.1); // near the middle axis
    return scene;
}

TEST(IntegratorLimits, ImplicitGyroStaysBoundedAtHugeSteps) {
    // h |w| = 50 is 80 times the bound under which its energy provably never rises
    // (integrator_implicit_gyro.cpp): it may gain a little, but it stays finite and bounded where
    // rk4, euler and symplectic_euler overflow within a dozen steps. Measured: max E / E0 =
    // 1.00009 over 2000 steps.
    World w = make_world(fast_spin(), Integrator::ImplicitGyro, 0.5);
    const double e0 = diagnose(w.model, w.state).energy();
    double worst = 0.0;
    for (int k = 0; k < 2000; ++k) {
        ASSERT_NO_THROW(step(w.model, w.state)) << "step " << k;
        worst = std::max(worst, diagnose(w.model, w.state).energy() / e0);
    }
    TUMBLE_MEASURED(worst, 1.01);
    EXPECT_LT(worst, 1.01);
}

TEST(IntegratorLimits, MidpointFailsLoudlyWhenNewtonCannotConverge) {
    World w = make_world(fast_spin(), Integrator::Midpoint, 0.5);
    try {
        testing::run(w, 100);
        FAIL() << "expected the Newton solve to give up";
    } catch (const DivergenceError& e) {
        EXPECT_EQ(e.body, 0);
        EXPECT_NE(std::string(e.what()).find("Newton"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("body 0"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace tumble::physics
