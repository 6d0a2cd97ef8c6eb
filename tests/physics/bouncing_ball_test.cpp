// The bouncing ball against its closed form, at h, 2h and 4h (h = 1/960 s, so 4h is the default
// 1/240 s), with the measured error printed beside each bound.
//
// A ball dropped from h0 meets the plane at V_0 = sqrt(2 g h0) after t_0 = sqrt(2 h0 / g). With
// restitution e and threshold v_th on the approach speed (docs/contacts.md), impact k (k = 0, 1,
// ...) comes at V_k = e^k V_0 and bounces when V_k >= v_th, leaving at e V_k and landing again
// 2 e V_k / g later. So the ball bounces n = #{k : e^k V_0 >= v_th} times and comes to rest at
// its first impact slower than v_th:
//   T_rest = t_0 + sum_{k<n} 2 e V_k / g.
// With v_th = 0 it bounces forever in finite time (Zeno): T = t_0 (1 + 2e / (1 - e)).
#include "physics/scenes/contact_scenes.h"
#include "scene_sim.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tumble::physics {
namespace {

using test::Sim;

constexpr double kH = 1.0 / 960.0;
constexpr double kG = 9.81;
constexpr double kRadius = 0.1; // scenes::ball_drop's ball
const double kSteps[] = {kH, 2 * kH, 4 * kH};

struct Bounces {
    int count = 0;       // impacts that sent the ball back up faster than 1 cm/s
    double rest = -1.0;  // time of the last step at which the ball still moved
    double max_gain = 0; // largest rise of the ball's energy over one step, J/kg
    double last_speed = 0;
};

// Steps a dropped ball for `seconds` and records its bounces, its rest time and whether any step
// raised its mechanical energy E = 1/2 v^2 + g z (per kg; z of the centre above its resting
// height). Semi-implicit Euler under constant gravity changes E by at most g^2 h^2 per free step,
// far below what an impact adds when it adds anything.
Bounces drop(double e, double threshold, double dt, double seconds) {
    scenes::Scene scene = scenes::ball_drop(e, 1.0, dt);
    scene.world.contact.restitution_threshold = threshold;
    scene.world.contact.sleeping = false; // rest must come from the contact, not from sleep
    Sim run(scene);
    Bounces b;
    auto energy = [&] {
        const double z = run.state.x[1].z() - kRadius;
        return 0.5 * run.state.v[1].squaredNorm() + kG * z;
    };
    for (int k = 0; k < run.steps_for(seconds); ++k) {
        const double e0 = energy(), vz0 = run.state.v[1].z();
        run.steps(1);
        const double vz = run.state.v[1].z();
        if (vz0 < 0.0 && vz > 0.01) ++b.count;
        b.max_gain = std::max(b.max_gain, energy() - e0 - kG * kG * dt * dt);
        if (run.state.v[1].norm() > 1e-3) b.rest = (k + 1) * run.model.dt;
    }
    b.last_speed = run.state.v[1].norm();
    return b;
}

double closed_form_rest(double e, double threshold, int& bounces) {
    const double v0 = std::sqrt(2.0 * kG * 1.0);
    double t = std::sqrt(2.0 / kG), v = v0;
    bounces = 0;
    while (v >= threshold && bounces < 1000) {
        t += 2.0 * e * v / kG;
        v *= e;
        ++bounces;
    }
    return t;
}

TEST(BouncingBall, CountAndRestTimeFollowTheClosedFormForSeveralEAndThresholds) {
    struct Case {
        double e, threshold;
    };
    for (const Case c : {Case{0.8, 0.5}, Case{0.8, 1.0}, Case{0.5, 0.5}, Case{0.5, 2.0}}) {
        int expected_count = 0;
        const double expected_rest = closed_form_rest(c.e, c.threshold, expected_count);
        for (double dt : kSteps) {
            const Bounces b = drop(c.e, c.threshold, dt, expected_rest + 1.0);
            std::printf("e = %.1f, threshold %.1f m/s, dt = 1/%.0f s: %d bounces (closed form "
                        "%d), rest at %.4f s (closed form %.4f s)\n",
                        c.e, c.threshold, 1.0 / dt, b.count, expected_count, b.rest, expected_rest);
            EXPECT_EQ(b.count, expected_count) << "e " << c.e << " threshold " << c.threshold;
            // Each of the n + 1 impacts is placed within one step of its exact time (the rest
            // time is read to the step), and the flights in between carry the error along.
            const double rest_error = std::abs(b.rest - expected_rest);
            const double bound = (expected_count + 1) * dt;
            TUMBLE_MEASURED(rest_error, bound);
            EXPECT_LT(rest_error, bound);
            EXPECT_LT(b.last_speed, 1e-6);
        }
    }
}

// Threshold 0: the bounces get ever slower, and the slow ones must not add energy at any step
// (they did at dt = 1e-3 and 5e-4: 0.05 m/s in, 0.07 m/s out, hopping to the end of the run).
// The ball comes to rest near the Zeno time, after which nothing moves.
TEST(BouncingBall, SlowImpactsAddNoEnergyAtAnyStep) {
    const double e = 0.8, zeno = std::sqrt(2.0 / kG) * (1.0 + 2.0 * e / (1.0 - e));
    for (double dt : {kH, 2 * kH, 4 * kH, 1e-3, 5e-4}) {
        const Bounces b = drop(e, 0.0, dt, 8.0);
        std::printf("dt = %.6f s: rest at %.4f s (Zeno %.4f s)\n", dt, b.rest, zeno);
        TUMBLE_MEASURED(b.max_gain, 1e-9);
        EXPECT_LT(b.max_gain, 1e-9) << "dt " << dt;
        EXPECT_LT(b.last_speed, 1e-6) << "dt " << dt;
        const double early = zeno - b.rest; // the last, slowest hops are lost inside one step
        TUMBLE_MEASURED(early, 0.3);
        EXPECT_GT(early, -2 * dt);
        EXPECT_LT(early, 0.3);
    }
}

} // namespace
} // namespace tumble::physics
