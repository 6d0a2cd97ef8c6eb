// Lesson 4 (docs/lessons/04-intermediate-axis.md): the book of
// assets/scenes/lessons/intermediate_axis.json, run as the app runs it, flips when and as often as
// the exact solution says. A flip is the middle axis turning over: its component of L,
// m2 = (R e2) . L, changes sign. The exact m(t) = (alpha cn u, beta sn u, gamma dn u), u = u0 + nu
// t (physics/exact/free_rigid_body.h, docs/exact-solutions.md section 3), has m2 = beta sn u, which
// vanishes every 2 K(k) / |nu|, and returns to its start (the polhode closes) after 4 K(k) / |nu|.
// That oracle is Jacobi's closed form, independent of every integrator; the moments come from the
// box formula here, not from the model.
#include "lesson_support.h"

#include "physics/exact/free_rigid_body.h"

namespace tumble::test {
namespace {

constexpr const char* kLesson = "04-intermediate-axis.md";

// Times where f (sampled every dt from 0 to `end`) changes sign, each refined by bisection when
// `refine` is given, else by linear interpolation between the samples.
template <class F>
std::vector<double> sign_changes(F f, double dt, double end, bool refine) {
    std::vector<double> out;
    double t0 = 0.0, f0 = f(0.0);
    for (double t1 = dt; t1 <= end + 1e-12; t1 += dt) {
        const double f1 = f(t1);
        if ((f0 < 0) != (f1 < 0)) {
            double a = t0, b = t1, fa = f0;
            for (int i = 0; refine && i < 60; ++i) {
                const double mid = 0.5 * (a + b), fm = f(mid);
                ((fm < 0) == (fa < 0) ? a : b) = mid;
                if ((fm < 0) == (fa < 0)) fa = fm;
            }
            out.push_back(refine ? 0.5 * (a + b) : t0 + (t1 - t0) * f0 / (f0 - f1));
        }
        t0 = t1, f0 = f1;
    }
    return out;
}

TEST(Lessons, TheBookFlipsWhenJacobisSolutionSays) {
    const app::Scene scene = lesson_scene("intermediate_axis");
    const physics::BodyDef& b = scene.bodies[1];
    const physics::Vec3 s = 2.0 * b.shape.half_extents;
    const physics::Vec3 inertia(b.mass * (s.y() * s.y() + s.z() * s.z()) / 12,
                                b.mass * (s.x() * s.x() + s.z() * s.z()) / 12,
                                b.mass * (s.x() * s.x() + s.y() * s.y()) / 12);
    ASSERT_TRUE(inertia.z() < inertia.x() && inertia.x() < inertia.y()) << "x is the middle axis";
    const exact::ExactFreeRigidBody oracle(inertia, b.orientation, b.angular_velocity);
    const physics::Vec3 L = oracle.angular_momentum();

    // The simulation, sampled at every step: m2 = (R e1) . L for the book's x axis (the middle).
    app::Simulation sim = lesson_simulation(scene);
    const double h = sim.model.dt;
    std::vector<double> m2;
    for (double t = 0; t <= scene.duration + 1e-9; t += h) {
        if (t > 0) sim.step();
        const physics::Quat q = physics::body_pose(sim.model, sim.state, 1).orientation;
        m2.push_back((q * physics::Vec3::UnitX()).dot(L));
    }
    const auto simulated = sign_changes(
        [&](double t) { return m2[std::size_t(std::lround(t / h))]; }, h, scene.duration, false);
    const auto exact_flips = sign_changes([&](double t) { return oracle.body_momentum_at(t).x(); },
                                          h, scene.duration, true);

    ASSERT_GE(exact_flips.size(), 3u);
    ASSERT_EQ(simulated.size(), exact_flips.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < simulated.size(); ++i)
        worst = std::max(worst, std::abs(simulated[i] - exact_flips[i]));
    TUMBLE_MEASURED(worst, 2e-3);
    EXPECT_LT(worst, 2e-3); // seconds: splitting's phase error and the interpolation of samples

    const double interval = oracle.body_period() / 2; // 2 K(k) / |nu|
    const double measured_interval =
        (simulated.back() - simulated.front()) / double(simulated.size() - 1);
    TUMBLE_MEASURED(std::abs(measured_interval - interval), 1e-3);
    EXPECT_NEAR(measured_interval, interval, 1e-3);
    expect_quoted(kLesson, "first_flip", simulated.front());
    expect_quoted(kLesson, "flip_interval", measured_interval);
    expect_quoted(kLesson, "polhode_period", oracle.body_period());
    expect_quoted(kLesson, "modulus", oracle.modulus());
    expect_quoted(kLesson, "flips_in_run", double(simulated.size()));
}

} // namespace
} // namespace tumble::test
