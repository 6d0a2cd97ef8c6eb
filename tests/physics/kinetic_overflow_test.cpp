// A body in free flight whose kinetic energy overflows a double stops the run like a state that is
// not finite: v and w of 1e160 are finite, but m |v|^2 and I |w|^2 are not, and every energy
// diagnostic after them would be inf.
#include "physics/build.h"
#include "physics/diagnostics.h"
#include "physics/step.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::physics {
namespace {

// Empty space stepped with explicit Euler, whose rotation update keeps the orientation finite at
// any finite w (rk4's and the splittings' do not at 1e160).
WorldDef empty_space() {
    WorldDef w;
    w.gravity = Vec3::Zero();
    w.integrator = Integrator::Euler;
    return w;
}

// Steps one sphere in empty space until DivergenceError (at most 10 steps).
DivergenceError first_divergence(const BodyDef& b) {
    const WorldDef w = empty_space();
    const Model m = build_model(w, {b});
    State s = initial_state(m, {b});
    try {
        for (int k = 0; k < 10; ++k) step(m, s);
    } catch (const DivergenceError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a DivergenceError; energy " << diagnose(m, s).energy();
    return DivergenceError(-1, -1, "", "");
}

TEST(KineticOverflow, ASpeedWhoseSquareOverflowsStopsTheRunAfterStepOne) {
    BodyDef b;
    b.velocity = Vec3(1e160, 0.0, 0.0);
    const DivergenceError e = first_divergence(b);
    EXPECT_EQ(e.body, 0);
    EXPECT_EQ(e.step, 1);
    EXPECT_EQ(e.quantity, "kinetic energy m |v|^2");
    EXPECT_NE(
        std::string(e.what()).find("body 0: kinetic energy m |v|^2 is not finite after step 1"),
        std::string::npos)
        << e.what();
}

TEST(KineticOverflow, AnAngularSpeedWhoseSquareOverflowsStopsTheRunAfterStepOne) {
    BodyDef b; // a sphere: no gyroscopic term, so w itself stays finite
    b.angular_velocity = Vec3(0.0, 1e160, 0.0);
    const DivergenceError e = first_divergence(b);
    EXPECT_EQ(e.step, 1);
    EXPECT_EQ(e.quantity, "rotational kinetic energy I |w|^2");
}

TEST(KineticOverflow, LargeButFiniteEnergiesRunOn) {
    BodyDef b;
    b.velocity = Vec3(1e150, 0.0, 0.0);
    b.angular_velocity = Vec3(0.0, 1e150, 0.0);
    const WorldDef w = empty_space();
    const Model m = build_model(w, {b});
    State s = initial_state(m, {b});
    for (int k = 0; k < 10; ++k) step(m, s);
    EXPECT_TRUE(std::isfinite(diagnose(m, s).energy()));
}

} // namespace
} // namespace tumble::physics
