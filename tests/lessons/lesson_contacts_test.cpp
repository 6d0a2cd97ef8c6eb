// Lesson 10 (docs/lessons/10-contacts.md): what the contact stage does, against the classical
// results written out here.
//  - The bouncing ball (assets/scenes/lessons/bouncing_ball.json): dropped from h0, it falls for
//    t0 = sqrt(2 h0 / g) and meets the ground at v0 = g t0; Newton's restitution e sends it back
//    at e v, so each apex is e^2 of the last and each flight 2 e^k t0; summed for ever the bounces
//    end at t0 (1 + e) / (1 - e) (Zeno). Tumble stops it sooner: an impact slower than the
//    restitution threshold v_th does not bounce (Box2D's rule), so the ball bounces while
//    v0 e^k >= v_th and rests at t0 (1 + 2 e (1 - e^n) / (1 - e)) after n bounces.
//  - Blocks on ramps (friction.json): static friction holds while tan(theta) <= mu; sliding, a
//    block accelerates at g (sin(theta) - mu cos(theta)).
//  - A ball rolling without slipping down a ramp: a = g sin(theta) / (1 + I / (m r^2)) = 5/7 g
//    sin(theta) for a solid sphere (I = 2/5 m r^2).
//  - A ball thrown sliding with no spin on level ground: friction mu m g slows v at mu g and spins
//    it up at 5/2 mu g / r until v = w r: at t = 2 v0 / (7 mu g), speed 5/7 v0, after
//    12 v0^2 / (49 mu g) of sliding.
#include "lesson_support.h"

#include <numbers>

namespace tumble::test {
namespace {

constexpr const char* kLesson = "10-contacts.md";
constexpr double kDeg = 180 / std::numbers::pi;

struct Bounces {
    std::vector<double> apexes; // heights of the ball's bottom at each apex after a bounce
    int count = 0;              // bounces: the vertical velocity turned from down to up
    double rest = -1;           // s: when it stopped for good (|v| below 1 mm/s, never above again)
};

Bounces bounce(const app::Scene& scene) {
    app::Simulation sim = lesson_simulation(scene);
    const int b = body_index(scene, "ball");
    const double r = scene.bodies[b].shape.radius, h = sim.model.dt;
    Bounces out;
    double last_vz = sim.state.v[b].z();
    const auto steps = static_cast<int>(std::lround(scene.duration / h));
    for (int k = 1; k <= steps; ++k) {
        const double z_before = sim.state.x[b].z();
        sim.step();
        const double vz = sim.state.v[b].z();
        if (last_vz < 0 && vz > 0) ++out.count;
        if (last_vz > 0 && vz <= 0 && out.count > 0)
            out.apexes.push_back(std::max(z_before, sim.state.x[b].z()) - r);
        if (sim.state.v[b].norm() < 1e-3) {
            if (out.rest < 0) out.rest = k * h;
        } else {
            out.rest = -1;
        }
        last_vz = vz;
    }
    return out;
}

TEST(Lessons, TheBallBouncesToESquaredUntilTheThresholdStopsIt) {
    const app::Scene scene = lesson_scene("bouncing_ball");
    const int b = body_index(scene, "ball");
    const double g = -scene.world.gravity.z(), e = scene.bodies[b].material.restitution;
    const double h0 = scene.bodies[b].position.z() - scene.bodies[b].shape.radius;
    const double t0 = std::sqrt(2 * h0 / g), v0 = g * t0,
                 vth = scene.world.contact.restitution_threshold;
    int n = 0;
    while (v0 * std::pow(e, n) >= vth) ++n; // impacts 0 .. n-1 bounce
    const double rest = t0 * (1 + 2 * e * (1 - std::pow(e, n)) / (1 - e));
    const double zeno = t0 * (1 + e) / (1 - e);

    const Bounces run = bounce(scene);
    ASSERT_GE(run.apexes.size(), 3u);
    EXPECT_EQ(run.count, n);
    const double first_ratio = run.apexes[0] / h0, second_ratio = run.apexes[1] / run.apexes[0];
    TUMBLE_MEASURED(std::abs(first_ratio / (e * e) - 1), 0.01);
    TUMBLE_MEASURED(std::abs(run.rest - rest), 0.02);
    EXPECT_NEAR(first_ratio / (e * e), 1.0, 0.01);
    EXPECT_NEAR(second_ratio / (e * e), 1.0, 0.01);
    EXPECT_NEAR(run.rest, rest, 0.02); // s: within a few steps

    expect_quoted(kLesson, "fall_time", t0);
    expect_quoted(kLesson, "impact_speed", v0);
    expect_quoted(kLesson, "e_squared", e * e);
    expect_quoted(kLesson, "first_apex_ratio", first_ratio);
    expect_quoted(kLesson, "second_apex_ratio", second_ratio);
    expect_quoted(kLesson, "zeno_time", zeno);
    expect_quoted(kLesson, "bounces", double(n));
    expect_quoted(kLesson, "measured_bounces", double(run.count));
    expect_quoted(kLesson, "rest_time", rest);
    expect_quoted(kLesson, "measured_rest_time", run.rest);

    // Exercise: the same ball with e = 0.9 bounces while 4.43 (0.9)^k >= 0.5.
    app::Scene bouncier = scene;
    bouncier.bodies[b].material.restitution = 0.9;
    bouncier.duration = 10;
    int n9 = 0;
    while (v0 * std::pow(0.9, n9) >= vth) ++n9;
    EXPECT_EQ(bounce(bouncier).count, n9);
    expect_quoted(kLesson, "bounces_e09", double(n9));
}

// Distance (m) body b has moved along `along` since the start, sampled at every step.
struct Track {
    std::vector<double> t, s, speed, slip; // slip: |v of the contact point| for a ball
};

Track track(const app::Scene& scene, const std::string& name, const physics::Vec3& along,
            const physics::Vec3& down) {
    app::Simulation sim = lesson_simulation(scene);
    const int b = body_index(scene, name);
    const physics::Vec3 x0 = sim.state.x[b];
    const bool ball = scene.bodies[b].shape.kind == physics::ShapeKind::Sphere;
    const double r = ball ? scene.bodies[b].shape.radius : 0;
    Track out;
    const auto steps = static_cast<int>(std::lround(scene.duration / sim.model.dt));
    for (int k = 0; k <= steps; ++k) {
        if (k > 0) sim.step();
        out.t.push_back(k * sim.model.dt);
        out.s.push_back((sim.state.x[b] - x0).dot(along));
        out.speed.push_back(sim.state.v[b].dot(along));
        out.slip.push_back((sim.state.v[b] + sim.state.w[b].cross(r * down)).norm());
    }
    return out;
}

physics::Vec3 down_slope(double theta_deg) { // the ramps rise along +x
    const double t = theta_deg / kDeg;
    return {-std::cos(t), 0, -std::sin(t)};
}
physics::Vec3 into_ramp(double theta_deg) {
    const double t = theta_deg / kDeg;
    return {std::sin(t), 0, -std::cos(t)};
}

TEST(Lessons, FrictionHoldsBelowTheAngleOfReposeAndBallsRollAtFiveSevenths) {
    const app::Scene scene = lesson_scene("friction");
    const double g = -scene.world.gravity.z(), mu = 0.5;
    // The scene's coefficients: sqrt(mu_ramp mu_block) = 0.5.
    EXPECT_DOUBLE_EQ(std::sqrt(scene.bodies[body_index(scene, "ramp 30")].material.friction *
                               scene.bodies[body_index(scene, "block 30")].material.friction),
                     mu);
    const Track held = track(scene, "block 20", down_slope(20), into_ramp(20));
    const Track slid = track(scene, "block 30", down_slope(30), into_ramp(30));
    const Track rolled = track(scene, "rolling ball", down_slope(15), into_ramp(15));
    const double slide_a = g * (std::sin(30 / kDeg) - mu * std::cos(30 / kDeg));
    const double roll_a = 5.0 / 7.0 * g * std::sin(15 / kDeg);
    // Accelerations: the slope of the speed along the ramp after the first 0.1 s.
    const auto fit = [](const Track& tr) {
        const std::size_t from = tr.t.size() / 12;
        return slope(std::vector<double>(tr.t.begin() + long(from), tr.t.end()),
                     std::vector<double>(tr.speed.begin() + long(from), tr.speed.end()));
    };
    const double held_moved = *std::max_element(held.s.begin(), held.s.end());
    const double slid_a = fit(slid), rolled_a = fit(rolled);
    const double worst_roll_slip =
        *std::max_element(rolled.slip.begin() + long(rolled.slip.size() / 12), rolled.slip.end());
    // Held by static friction, it creeps no further than the contact tolerance the solver's effort
    // follows (world.contact_tolerance; the default, as the scene sets none).
    const double creep_bound = scene.world.contact.tolerance;
    TUMBLE_MEASURED(held_moved, creep_bound);
    TUMBLE_MEASURED(std::abs(slid_a / slide_a - 1), 0.01);
    TUMBLE_MEASURED(std::abs(rolled_a / roll_a - 1), 0.01);
    TUMBLE_MEASURED(worst_roll_slip, 0.01);
    EXPECT_LT(held_moved, creep_bound); // m
    EXPECT_NEAR(slid_a / slide_a, 1.0, 0.01);
    EXPECT_NEAR(rolled_a / roll_a, 1.0, 0.01);
    EXPECT_LT(worst_roll_slip, 0.01); // m/s at the contact point: rolling, not sliding

    expect_quoted(kLesson, "tan_20", std::tan(20 / kDeg));
    expect_quoted(kLesson, "tan_30", std::tan(30 / kDeg));
    expect_quoted(kLesson, "held_moved", 1000 * held_moved);
    expect_quoted(kLesson, "slide_accel", slide_a);
    expect_quoted(kLesson, "measured_slide_accel", slid_a);
    expect_quoted(kLesson, "roll_accel", roll_a);
    expect_quoted(kLesson, "measured_roll_accel", rolled_a);
    // Exercises: the steepest ramp mu = 0.5 holds, and the least friction that keeps the ball on
    // the 15 degree ramp rolling (friction needed: 2/7 m g sin(theta) <= mu m g cos(theta)).
    expect_quoted(kLesson, "angle_of_repose", kDeg * std::atan(mu));
    expect_quoted(kLesson, "least_rolling_mu", 2.0 / 7.0 * std::tan(15 / kDeg));
}

TEST(Lessons, ABallThrownSlidingStartsRollingAtFiveSeventhsOfItsSpeed) {
    const app::Scene scene = lesson_scene("friction");
    const int b = body_index(scene, "sliding ball");
    const double g = -scene.world.gravity.z();
    const double mu = std::sqrt(scene.bodies[b].material.friction *
                                scene.bodies[body_index(scene, "ground")].material.friction);
    const double v0 = scene.bodies[b].velocity.x();
    const double t_roll = 2 * v0 / (7 * mu * g), v_roll = 5.0 / 7.0 * v0,
                 d_roll = 12 * v0 * v0 / (49 * mu * g);
    const Track tr = track(scene, "sliding ball", physics::Vec3::UnitX(), -physics::Vec3::UnitZ());
    std::size_t k = 0;
    while (k < tr.t.size() && tr.slip[k] > 1e-3) ++k; // m/s: the contact point at rest
    ASSERT_LT(k, tr.t.size()) << "never rolls";
    TUMBLE_MEASURED(std::abs(tr.t[k] - t_roll), 0.01);
    TUMBLE_MEASURED(std::abs(tr.speed.back() / v_roll - 1), 0.005);
    EXPECT_NEAR(tr.t[k], t_roll, 0.01); // s: within two steps
    EXPECT_NEAR(tr.speed.back() / v_roll, 1.0, 0.005);
    EXPECT_NEAR(tr.s[k], d_roll, 0.02); // m
    expect_quoted(kLesson, "roll_time", t_roll);
    expect_quoted(kLesson, "measured_roll_time", tr.t[k]);
    expect_quoted(kLesson, "roll_speed", v_roll);
    expect_quoted(kLesson, "measured_roll_speed", tr.speed.back());
    expect_quoted(kLesson, "roll_distance", d_roll);
    expect_quoted(kLesson, "measured_roll_distance", tr.s[k]);
}

} // namespace
} // namespace tumble::test
