// Contacts against exact physics, each at h, 2h and 4h (h = 1/240 s), measured values printed
// beside their bounds.
#include "physics/diagnostics.h"
#include "physics/scenes/contact_scenes.h"
#include "scene_sim.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace tumble::physics {
namespace {

using test::Sim;

constexpr double kH = 1.0 / 240.0;
constexpr double kG = 9.81;
const double kSteps[] = {kH, 2 * kH, 4 * kH};

// Ball dropped from h0 with restitution e: the n-th apex is e^(2n) h0. The apex after each bounce
// is taken from the free-flight energy z + v^2 / 2g at the first step where the ball is at least
// 2 cm up and rising (exact for the parabola, whatever the sampling).
TEST(ContactPhysics, BouncingBallApexesFollowE2n) {
    const double e = 0.8, h0 = 1.0;
    for (double dt : kSteps) {
        Sim run(scenes::ball_drop(e, h0, dt));
        std::vector<double> apex;
        bool armed = false;
        for (int k = 0; k < run.steps_for(6.0) && apex.size() < 5; ++k) {
            const double vz_before = run.state.v[1].z();
            run.steps(1);
            const double z = run.state.x[1].z() - 0.1, vz = run.state.v[1].z();
            if (vz_before < 0.0 && vz > 0.0) armed = true; // bounced
            if (armed && z > 0.02 && vz > 0.0) {
                apex.push_back(z + vz * vz / (2 * kG));
                armed = false;
            }
        }
        ASSERT_EQ(apex.size(), 5u) << "dt " << dt;
        double worst = 0.0;
        for (int n = 1; n <= 5; ++n) {
            const double expected = std::pow(e, 2 * n) * h0;
            worst = std::max(worst, std::abs(apex[n - 1] / expected - 1.0));
        }
        std::printf("dt = %.6f s: ", dt);
        TUMBLE_MEASURED(worst, 0.02);
        EXPECT_LT(worst, 0.02);

        // Then it comes to rest on the plane (and, sleeping by default, falls asleep).
        run.steps(run.steps_for(8.0));
        const double rest_speed = run.state.v[1].norm();
        const double rest_gap = std::abs(run.state.x[1].z() - 0.1);
        TUMBLE_MEASURED(rest_speed, 1e-6);
        TUMBLE_MEASURED(rest_gap, 1e-3);
        EXPECT_LT(rest_speed, 1e-6);
        EXPECT_LT(rest_gap, 1e-3);
        EXPECT_TRUE(run.state.sleep.asleep[1]);
    }
}

// Sliding: a = g (sin a - mu cos a) when tan a > mu, measured from the velocity along the slope.
TEST(ContactPhysics, BoxSlidesDownInclineAtCoulombRate) {
    const double angle = 30.0 * std::numbers::pi / 180.0, mu = 0.3;
    const double expected = kG * (std::sin(angle) - mu * std::cos(angle));
    const Vec3 downhill = Quat(Eigen::AngleAxisd(angle, Vec3::UnitY())) * Vec3(1, 0, 0);
    for (double dt : kSteps) {
        Sim run(scenes::incline(angle, mu, dt, true));
        run.steps(run.steps_for(2.0));
        const double accel = run.state.v[1].dot(downhill) / run.state.time(run.model);
        const double err = std::abs(accel / expected - 1.0);
        std::printf("dt = %.6f s: a = %.6f m/s^2, expected %.6f: ", dt, accel, expected);
        TUMBLE_MEASURED(err, 0.02);
        EXPECT_LT(err, 0.02);
    }
}

// Sticking: with tan a < mu the box must not creep. Sleeping off, so that the solver (not
// sleep) has to hold it for the whole 10 s.
TEST(ContactPhysics, BoxOnShallowInclineDoesNotCreep) {
    const double angle = 20.0 * std::numbers::pi / 180.0, mu = 0.5; // tan 20 deg = 0.36
    for (double dt : kSteps) {
        Sim run(scenes::incline(angle, mu, dt, false));
        const Vec3 start = run.state.x[1];
        run.steps(run.steps_for(10.0));
        const double creep = (run.state.x[1] - start).norm();
        std::printf("dt = %.6f s: ", dt);
        TUMBLE_MEASURED(creep, 1e-3);
        EXPECT_LT(creep, 1e-3);
    }
}

// Newton's cradle: one ball in, one ball out; momentum kept to 1% through every step.
TEST(ContactPhysics, NewtonsCradleSendsOneBallOut) {
    const double v = 1.0;
    for (double dt : kSteps) {
        Sim run(scenes::cradle(v, dt));
        const double p0 = diagnose(run.model, run.state).linear_momentum.x();
        double worst_p = 0.0;
        for (int k = 0; k < run.steps_for(0.5); ++k) {
            run.steps(1);
            const double p = diagnose(run.model, run.state).linear_momentum.x();
            worst_p = std::max(worst_p, std::abs(p / p0 - 1.0));
        }
        double rest = 0.0;
        for (int i = 0; i < 4; ++i) rest = std::max(rest, run.state.v[i].norm() / v);
        const double out = std::abs(run.state.v[4].x() / v - 1.0);
        std::printf("dt = %.6f s: ", dt);
        TUMBLE_MEASURED(worst_p, 0.01);
        TUMBLE_MEASURED(out, 0.01);
        TUMBLE_MEASURED(rest, 0.01);
        EXPECT_LT(worst_p, 0.01);
        EXPECT_LT(out, 0.01);
        EXPECT_LT(rest, 0.01);
    }
}

double max_drift(const State& a, const State& b) {
    double d = 0.0;
    for (std::size_t i = 0; i < a.x.size(); ++i) d = std::max(d, (a.x[i] - b.x[i]).norm());
    return d;
}

TEST(ContactPhysics, TowerOfTenBoxesStands) {
    for (double dt : kSteps) {
        Sim run(scenes::box_stack(10, 0.5, dt));
        const State start = run.state;
        run.steps(run.steps_for(10.0));
        const double drift = max_drift(start, run.state); // includes the soft settling
        std::printf("dt = %.6f s: ", dt);
        TUMBLE_MEASURED(drift, 0.01);
        EXPECT_LT(drift, 0.01);
    }
}

TEST(ContactPhysics, PyramidOfTwentyBoxesStands) {
    for (double dt : kSteps) {
        Sim run(scenes::pyramid(dt));
        ASSERT_EQ(run.model.body_count(), 21);
        const State start = run.state;
        run.steps(run.steps_for(10.0));
        const double drift = max_drift(start, run.state);
        std::printf("dt = %.6f s: ", dt);
        TUMBLE_MEASURED(drift, 0.01);
        EXPECT_LT(drift, 0.01);
    }
}

// Nothing tunnels: speculative contacts with a speed-aware margin (collide.h) catch a 2 cm ball
// at 50 m/s (0.21 m per step at h, 0.83 m at 4h) in front of a 1 cm wall.
TEST(ContactPhysics, FastBallStopsAtThinWall) {
    for (double dt : kSteps) {
        Sim run(scenes::bullet(50.0, dt));
        double furthest = -1.0;
        for (int k = 0; k < run.steps_for(0.5); ++k) {
            run.steps(1);
            furthest = std::max(furthest, run.state.x[1].x());
        }
        const double limit = -0.005 - 0.02; // touching the wall's near face
        const double overshoot = furthest - limit;
        std::printf("dt = %.6f s: ", dt);
        TUMBLE_MEASURED(overshoot, 1e-3);
        EXPECT_LT(overshoot, 1e-3);
        EXPECT_LT(run.state.x[1].x(), 0.0);
    }
}

// A speculative contact that never closes applies nothing: two spheres at rest 1 mm apart (inside
// the 2 mm speculative distance), without gravity, keep a manifold every step and stay exactly
// where they are, with exactly zero velocity. The solver skips such points (no push, no friction
// yet); a bias or a friction impulse that leaked into them would move the spheres.
TEST(ContactPhysics, SpeculativeContactAtRestAppliesNothing) {
    for (double dt : kSteps) {
        scenes::Scene scene;
        scene.world.dt = dt;
        scene.world.gravity = Vec3::Zero();
        scene.world.contact.sleeping = false;
        for (double x : {-0.1005, 0.1005}) {
            BodyDef ball;
            ball.shape = Shape::sphere(0.1);
            ball.mass = 1.0;
            ball.position = Vec3(x, 0.0, 0.0);
            scene.bodies.push_back(ball);
        }
        Sim run(scene);
        const State start = run.state;
        run.steps(run.steps_for(2.0));
        EXPECT_EQ(run.state.contacts.size(), 1) << "dt = " << dt;
        for (int i = 0; i < 2; ++i) {
            EXPECT_EQ(run.state.x[i], start.x[i]) << "dt = " << dt << ", ball " << i;
            EXPECT_EQ(run.state.v[i], Vec3::Zero()) << "dt = " << dt << ", ball " << i;
            EXPECT_EQ(run.state.w[i], Vec3::Zero()) << "dt = " << dt << ", ball " << i;
        }
    }
}

} // namespace
} // namespace tumble::physics
