// The error estimate (physics/error_estimate.h) where its answer is known without it: the main run
// is the same bits with and without it; in free fall the symplectic and explicit Euler errors have
// closed forms; a body's estimate stops at its first contact (at the time the speculative margin
// says) or sleep and keeps its free-flight value; a body never in contact keeps an estimate that
// matches its exact motion; a shadow that diverges stops the run naming body and step. The estimate
// against the exact oracles of every study problem is
// tests/app/study/error_estimate_oracle_test.cpp.
#include "physics/error_estimate.h"
#include "physics/exact/body_motion.h"
#include "physics/integrator.h"
#include "physics/scenes/contact_scenes.h"
#include "physics/scenes/reference_scenes.h"
#include "physics/scenes/state_hash.h"
#include "physics/step.h"
#include "scene_sim.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::physics::test {
namespace {

constexpr double kG = 9.81;

State run_plain(const Model& m, State s, std::int64_t steps) {
    for (std::int64_t k = 0; k < steps; ++k) step(m, s);
    return s;
}

// The main run with the estimate beside it: the same bits as without (a torque-free book, and
// contacts with impacts, friction, sleeping).
TEST(ErrorEstimate, MainRunIsBitIdenticalWithAndWithoutIt) {
    for (const scenes::Scene& scene :
         {scenes::intermediate_axis_scene(), scenes::ball_drop(0.8, 1.0, 1.0 / 240),
          scenes::box_stack(3, 0.4, 1.0 / 240), scenes::pyramid(1.0 / 240)}) {
        for (Integrator id : {Integrator::Rk4, Integrator::SymplecticEuler, Integrator::Midpoint}) {
            scenes::Scene s = scene;
            s.world.integrator = id;
            Sim sim(s);
            const std::int64_t steps = 480;
            const State plain = run_plain(sim.model, sim.state, steps);
            State with = sim.state;
            ErrorEstimator e(sim.model, with);
            for (std::int64_t k = 0; k < steps; ++k) {
                step(sim.model, with);
                e.advance(with);
            }
            EXPECT_EQ(scenes::state_hash(with), scenes::state_hash(plain)) << scene.name;
            const RunEstimate whole = estimate_run(sim.model, sim.state, steps, 100);
            EXPECT_EQ(scenes::state_hash(whole.final_state), scenes::state_hash(plain))
                << scene.name;
            EXPECT_EQ(e.time(), with.time(sim.model));
        }
    }
}

TEST(ErrorEstimate, RichardsonFactorIsOneOverOneMinusTwoToTheMinusP) {
    // e_h = C h^p, e_{h/2} = C h^p / 2^p: e_h = (e_h - e_{h/2}) / (1 - 2^-p).
    EXPECT_EQ(richardson_factor(1), 2.0);
    EXPECT_EQ(richardson_factor(2), 4.0 / 3.0);
    EXPECT_EQ(richardson_factor(4), 16.0 / 15.0);
    EXPECT_EQ(richardson_factor(0), 1.0);  // exact up to round-off: the raw difference
    EXPECT_EQ(richardson_factor(-1), 1.0); // a sentinel order for such a method
}

// A ball falling freely (no ground): symplectic Euler's z_n = z0 - g h^2 n (n + 1) / 2 runs
// g h t / 2 behind the exact z0 - g t^2 / 2, explicit Euler's z0 - g h^2 n (n - 1) / 2 as much
// ahead. Both are exactly first order in h, so the estimate at every time is the true error
// g h t / 2 (to round-off), and the orientation estimate is 0 (no spin).
TEST(ErrorEstimate, FreeFallErrorOfTheEulerMethodsIsGHTOverTwo) {
    for (Integrator id : {Integrator::SymplecticEuler, Integrator::Euler}) {
        scenes::Scene s;
        s.world.integrator = id;
        s.world.dt = 1.0 / 240;
        BodyDef ball;
        ball.shape = Shape::sphere(0.1);
        s.bodies = {ball};
        Sim sim(s);
        const RunEstimate r = estimate_run(sim.model, sim.state, 480, 48);
        ASSERT_EQ(r.samples.size(), 10u);
        double worst = 0.0;
        for (const EstimateSample& sample : r.samples) {
            const double expected = kG * s.world.dt * sample.t / 2;
            worst = std::max(worst, std::abs(sample.at[0].position / expected - 1));
            EXPECT_EQ(sample.at[0].rotation, 0.0);
            EXPECT_EQ(sample.holds[0], 1);
        }
        TUMBLE_MEASURED(worst, 1e-9); // measured 1.39e-12 (symplectic), 1.40e-12 (explicit)
        EXPECT_LT(worst, 1e-9);
        EXPECT_NEAR(r.bodies[0].max.position, kG * s.world.dt * 2.0 / 2, 1e-9);
        EXPECT_TRUE(r.bodies[0].holds());
    }
}

// The ball of ball_drop (bottom 1 m above the ground) with symplectic Euler at h = 1/240 s. The
// contact stage takes the ball from the start of the first step whose start has its gap
// z_n - r = 1 - g h^2 n (n + 1) / 2 within the speculative margin 2 mm + h |v_n| + h^2 g / 2,
// v_n = g h n (physics/contact_find.cpp, pair_margin); the estimate holds up to that time and
// keeps its value there,
// g h t / 2.
TEST(ErrorEstimate, BallDropStopsHoldingAtItsFirstContact) {
    const double h = 1.0 / 240;
    scenes::Scene s = scenes::ball_drop(0.8, 1.0, h);
    s.world.integrator = Integrator::SymplecticEuler;
    Sim sim(s);
    int n = 0;
    const double base = 0.002 + h * h * kG / 2; // the margin's terms other than h |v_n|
    while (1.0 - kG * h * h * n * (n + 1) / 2 > base + h * kG * h * n) ++n;
    const double first_contact = n * h;             // the start of step n + 1
    const double touch = std::sqrt(2.0 * 1.0 / kG); // the exact free fall meets the ground
    const RunEstimate r = estimate_run(sim.model, sim.state, 480, 1);
    ASSERT_EQ(r.bodies.size(), 1u);
    const BodyEstimate& ball = r.bodies[0];
    EXPECT_FALSE(ball.holds());
    EXPECT_EQ(ball.limit, EstimateLimit::Contact);
    // measured: first contact 0.4458 s (n = 107), the ground met at 0.4515 s
    TUMBLE_MEASURED(ball.valid_until, first_contact);
    EXPECT_NEAR(ball.valid_until, first_contact, 1e-12);
    EXPECT_LT(ball.valid_until, touch);
    EXPECT_LT(touch - ball.valid_until, (base + h * kG * touch) / (kG * touch) + 2 * h);
    // Kept from its last free-flight step: the closed-form error there, also its maximum.
    EXPECT_NEAR(ball.at.position, kG * h * first_contact / 2, 1e-9);
    EXPECT_NEAR(ball.max.position, kG * h * first_contact / 2, 1e-9);
    // Every sample after it says so.
    for (const EstimateSample& sample : r.samples)
        EXPECT_EQ(sample.holds[0], sample.t <= first_contact + 1e-12 ? 1 : 0) << sample.t;
}

// A stack resting on the ground is in contact from the first step: no estimate at all.
TEST(ErrorEstimate, BoxStackNeverHolds) {
    Sim sim(scenes::box_stack(3, 0.4, 1.0 / 240));
    const RunEstimate r = estimate_run(sim.model, sim.state, 10, 10);
    ASSERT_EQ(r.bodies.size(), 3u);
    for (const BodyEstimate& b : r.bodies) {
        EXPECT_EQ(b.limit, EstimateLimit::Contact);
        EXPECT_EQ(b.valid_until, 0.0);
        EXPECT_EQ(b.at.position, 0.0);
        EXPECT_EQ(b.at.rotation, 0.0);
    }
}

// Beside the bouncing ball, a book spinning high above it without gravity never meets anything:
// its estimate holds through the ball's bounces and matches its exact motion (the torque-free
// Jacobi solution), although the contact stage integrates every awake body in substeps while the
// ball is in contact.
TEST(ErrorEstimate, BodyNeverInContactKeepsAnEstimateThatMatchesItsExactMotion) {
    const double h = 1.0 / 120;
    scenes::Scene s = scenes::ball_drop(0.8, 1.0, h);
    BodyDef book = scenes::book();
    book.position = Vec3(3, 0, 20);
    book.gravity_scale = 0.0;
    book.angular_velocity = Vec3(0.2, 8.0, 0.3);
    s.bodies.push_back(book);
    s.world.integrator = Integrator::Midpoint;
    Sim sim(s);
    const int free_body = 2;
    exact::ExactBodyMotion exact(sim.model, sim.state, free_body);
    const std::int64_t steps = 240; // 2 s: three bounces
    const RunEstimate r = estimate_run(sim.model, sim.state, steps, steps);
    ASSERT_EQ(r.bodies.size(), 2u);
    EXPECT_FALSE(r.bodies[0].holds()); // the ball
    const BodyEstimate& b = r.bodies[1];
    ASSERT_EQ(b.body, free_body);
    EXPECT_TRUE(b.holds());
    const double truth = rotation_angle_between(exact.at(2.0).q, r.final_state.q[free_body]);
    const double ratio = b.at.rotation / truth;
    TUMBLE_MEASURED(ratio, 3.0); // measured 0.995 (true error 5.7e-03 rad)
    EXPECT_GT(ratio, 1.0 / 3);
    EXPECT_LT(ratio, 3.0);
}

// A body drifting at 1 cm/s without gravity in a scene with contacts falls asleep after 0.5 s
// (slower than the 5 cm/s sleep speed): its motion stops, in both runs, so their difference would
// say nothing: the estimate stops holding there.
TEST(ErrorEstimate, SleepStopsTheEstimate) {
    const double h = 1.0 / 240;
    scenes::Scene s = scenes::ball_drop(0.0, 1.0, h);
    BodyDef drifter;
    drifter.shape = Shape::sphere(0.1);
    drifter.position = Vec3(5, 0, 10);
    drifter.velocity = Vec3(0.01, 0, 0);
    drifter.gravity_scale = 0.0;
    s.bodies.push_back(drifter);
    Sim sim(s);
    const RunEstimate r = estimate_run(sim.model, sim.state, 240, 240);
    const BodyEstimate& b = r.bodies[1];
    EXPECT_EQ(b.limit, EstimateLimit::Sleep);
    TUMBLE_MEASURED(b.valid_until, 0.5); // measured 0.5 s: the start of the step it slept in
    EXPECT_GE(b.valid_until, 0.5 - 2 * h);
    EXPECT_LE(b.valid_until, 0.5);
}

// A shadow that diverges while the main run does not is a loud failure naming body and step: here
// the shadow is started from a state whose body 1 has no finite velocity (a constructed case: the
// shadow at h/2 is the more stable run, so no scene of ours makes it diverge first).
TEST(ErrorEstimate, ShadowDivergenceNamesBodyAndStep) {
    Sim sim(scenes::ball_drop(0.8, 1.0, 1.0 / 240));
    State bad = sim.state;
    bad.v[1] = Vec3(std::nan(""), 0, 0);
    ErrorEstimator e(sim.model, bad);
    step(sim.model, sim.state);
    try {
        e.advance(sim.state);
        FAIL() << "no error";
    } catch (const ShadowDivergenceError& err) {
        EXPECT_EQ(err.body, 1);
        EXPECT_EQ(err.step, 1);      // the shadow's first step
        EXPECT_EQ(err.main_step, 1); // during the main run's first
        const std::string what = err.what();
        EXPECT_NE(what.find("body 1"), std::string::npos) << what;
        EXPECT_NE(what.find("shadow run"), std::string::npos) << what;
        EXPECT_NE(what.find("main step 1"), std::string::npos) << what;
    }
}

// The estimator follows the main run step by step; a skipped or restored step is refused.
TEST(ErrorEstimate, RefusesAMainRunThatSkippedAStep) {
    Sim sim(scenes::intermediate_axis_scene());
    ErrorEstimator e(sim.model, sim.state);
    sim.steps(2);
    EXPECT_THROW(e.advance(sim.state), std::logic_error);
}

// The shadow's model: h/2, with the main run's number of contact substeps per step where the
// effort is fixed.
TEST(ErrorEstimate, ShadowHalvesTheStepAndEverySubstep) {
    Sim sim(scenes::ball_drop(0.8, 1.0, 1.0 / 240));
    // Fixed effort (world.iterations set): every awake body steps in the contact substeps; the
    // shadow keeps their count, so each is halved.
    Model fixed = sim.model;
    fixed.contact.iterations = 3;
    const Model shadow = half_step_model(fixed);
    EXPECT_EQ(shadow.dt, sim.model.dt / 2);
    EXPECT_EQ(substep_count(shadow.contact, shadow.dt), 6); // 6 at 1/240 s (1440 per second)
    EXPECT_EQ(substep_count(fixed.contact, fixed.dt), 6);
    // Effort on demand (the default, issue 28): a body in no contact flies over the whole step,
    // which the shadow halves; the shadow's islands choose their own substeps from h / 2.
    const Model on_demand = half_step_model(sim.model);
    EXPECT_EQ(on_demand.dt, sim.model.dt / 2);
    EXPECT_FALSE(fixed_effort(on_demand.contact));
}

} // namespace
} // namespace tumble::physics::test
