// Lesson 5 (docs/lessons/05-top-precession.md): the top of
// assets/scenes/lessons/top_precession.json (sharp_top.obj: a point tip on a table with friction
// 1), run as the app runs it, precesses at the rate of the heavy symmetric top with a fixed tip
// (Goldstein, Classical Mechanics, 3rd ed., section 5.7; Landau and Lifshitz, Mechanics, section
// 35). With the tilt theta of the axis a from the vertical, the spin w3 = w . a, the moments I3
// (axis) and I1' = I1 + m d^2 (across, about the tip) and the tip-to-centre distance d, steady
// precession (theta' = theta'' = 0) needs
//   I1' cos(theta) Omega^2 - I3 w3 Omega + m g d = 0,
// whose slow root is
//   Omega = (I3 w3 - sqrt(I3^2 w3^2 - 4 I1' cos(theta) m g d)) / (2 I1' cos theta)
//         = m g d / (I3 w3) (1 + eps + O(eps^2)),   eps = I1' cos(theta) m g d / (I3 w3)^2:
// the fast-top rate m g d / (I3 w3) is good to about eps, so it holds while (I3 w3)^2 is much
// larger than I1' m g d. The scene starts the top on that steady motion (w = Omega e_z +
// (w3 - Omega cos theta) a, v = Omega e_z x d a), checked here from the model's mass properties
// (physics/mesh_mass.cpp, checked against slices by TopPrecession.*).
#include "lesson_support.h"

#include <numbers>

namespace tumble::test {
namespace {

constexpr const char* kLesson = "05-top-precession.md";
constexpr double kPi = std::numbers::pi;

struct Top {
    double m, d, i1_tip, i3, g, theta, w3;
    physics::Vec3 axis;
    double fast() const { return m * g * d / (i3 * w3); }
    double eps() const { return i1_tip * std::cos(theta) * m * g * d / ((i3 * w3) * (i3 * w3)); }
    double exact() const {
        const double c = i1_tip * std::cos(theta), l = i3 * w3;
        return (l - std::sqrt(l * l - 4 * c * m * g * d)) / (2 * c);
    }
};

Top top_of(const app::Simulation& sim) {
    const physics::Model& model = sim.model;
    // The principal axis along the top's own z (the mass frame may order its axes otherwise).
    int k = 0;
    for (int j = 1; j < 3; ++j)
        if (std::abs((model.body_from_mass[1] * physics::Vec3::Unit(j)).z()) >
            std::abs((model.body_from_mass[1] * physics::Vec3::Unit(k)).z()))
            k = j;
    Top t{};
    t.m = model.mass[1];
    t.d = model.com_offset[1].norm();
    t.i3 = model.inertia[1][k];
    t.i1_tip = model.inertia[1][(k + 1) % 3] + t.m * t.d * t.d;
    t.g = -model.gravity.z();
    const physics::Quat q = physics::body_pose(model, sim.state, 1).orientation;
    t.axis = q * physics::Vec3::UnitZ();
    t.theta = std::acos(t.axis.z());
    t.w3 = sim.state.w[1].dot(t.axis);
    return t;
}

TEST(Lessons, TheTopPrecessesAtTheSteadyRateOfTheHeavyTop) {
    const app::Scene scene = lesson_scene("top_precession");
    app::Simulation sim = lesson_simulation(scene);
    const Top top = top_of(sim);
    const physics::Vec3 moments = sim.model.inertia[1];
    const double across = moments.sum() - top.i3; // the two other moments, equal for a top
    ASSERT_NEAR(across, 2 * (top.i1_tip - top.m * top.d * top.d), 1e-9 * across) << "symmetric";
    ASSERT_LT((sim.model.com_offset[1] - top.d * physics::Vec3::UnitZ()).norm(), 1e-12);

    // The scene starts on the steady precession.
    const double omega = top.exact();
    const physics::Vec3 ez = physics::Vec3::UnitZ();
    const physics::Vec3 w0 = omega * ez + (top.w3 - omega * std::cos(top.theta)) * top.axis;
    const physics::Vec3 v0 = omega * top.d * ez.cross(top.axis);
    const double start_error = std::max((sim.state.w[1] - w0).norm() / w0.norm(),
                                        (sim.state.v[1] - v0).norm() / v0.norm());
    TUMBLE_MEASURED(start_error, 1e-6);
    EXPECT_LT(start_error, 1e-6);

    // The axis' azimuth over one period of the steady rate, fitted by least squares.
    const double h = sim.model.dt;
    const auto steps = static_cast<int>(std::lround(2 * kPi / omega / h));
    std::vector<double> t, azimuth;
    double turned = 0, last = std::atan2(top.axis.y(), top.axis.x()), worst_tilt = 0;
    for (int k = 0; k <= steps; ++k) {
        if (k > 0) sim.step();
        const physics::Quat q = physics::body_pose(sim.model, sim.state, 1).orientation;
        const physics::Vec3 a = q * ez;
        turned = unwrap(turned, last, std::atan2(a.y(), a.x()));
        t.push_back(k * h);
        azimuth.push_back(turned);
        worst_tilt = std::max(worst_tilt, std::abs(std::acos(a.z()) - top.theta));
    }
    const double rate = slope(t, azimuth);
    const double exact_error = std::abs(rate / omega - 1),
                 fast_error = std::abs(rate / top.fast() - 1);
    TUMBLE_MEASURED(exact_error, 0.01);
    TUMBLE_MEASURED(fast_error, 2 * top.eps());
    TUMBLE_MEASURED(worst_tilt, 0.01);
    EXPECT_LT(exact_error, 0.01);
    EXPECT_LT(fast_error, 2 * top.eps()); // the fast-top formula is off by about eps
    EXPECT_LT(worst_tilt, 0.01);          // radians: steady, no visible nutation

    expect_quoted(kLesson, "mass", top.m);
    expect_quoted(kLesson, "tip_to_centre", 100 * top.d);
    expect_quoted(kLesson, "fast_rate", top.fast());
    expect_quoted(kLesson, "exact_rate", omega);
    expect_quoted(kLesson, "eps", 100 * top.eps());
    expect_quoted(kLesson, "measured_rate", rate);
    expect_quoted(kLesson, "period", 2 * kPi / rate);

    // The parallel-axis theorem: I1' = I1 + m d^2 about the tip.
    expect_quoted(kLesson, "i1_centre", 1e6 * (top.i1_tip - top.m * top.d * top.d));
    expect_quoted(kLesson, "i1_tip", 1e6 * top.i1_tip);
    // L about the tip: I3 w3 a + I1' W (e_z - cos(theta) a); the second part, of size
    // I1' W sin(theta), against the first.
    expect_quoted(kLesson, "spin_momentum", 1e3 * top.i3 * top.w3);
    expect_quoted(kLesson, "precession_momentum_ratio",
                  top.i1_tip * omega * std::sin(top.theta) / (top.i3 * top.w3));
    // Steady precession at this tilt needs (I3 w3)^2 >= 4 I1' cos(theta) m g d.
    expect_quoted(kLesson, "steady_threshold",
                  std::sqrt(4 * top.i1_tip * std::cos(top.theta) * top.m * top.g * top.d) / top.i3);
    // In a 60 fps video the top turns w3 / fps between frames; the eye sees the nearest turn.
    const double per_frame = top.w3 / scene.render.fps;
    expect_quoted(kLesson, "turn_per_frame", per_frame);
    expect_quoted(kLesson, "apparent_turn_per_frame", std::remainder(per_frame, 2 * kPi));
    expect_quoted(kLesson, "apparent_spin", std::remainder(per_frame, 2 * kPi) * scene.render.fps);
}

// Let go from a pure spin (axis at rest) the top nods: the fast-top estimates of the nutation,
// 2 I1' m g d sin(theta) / (I3 w3)^2 deep and 2 pi I1' / (I3 w3) long (Goldstein section 5.7),
// against the scene's top started that way (lesson 9 follows the exact theory).
TEST(Lessons, LetGoFromAPureSpinTheTopNodsByTheFastTopEstimate) {
    app::Scene scene = lesson_scene("top_precession");
    const Top base = top_of(lesson_simulation(scene));
    scene.bodies[1].angular_velocity = base.w3 * base.axis;
    scene.bodies[1].velocity = physics::Vec3::Zero();
    app::Simulation sim = lesson_simulation(scene);
    const Top top = top_of(sim);
    const double l3 = top.i3 * top.w3;
    const double depth = 2 * top.i1_tip * top.m * top.g * top.d * std::sin(top.theta) / (l3 * l3);
    const double period = 2 * kPi * top.i1_tip / l3;
    double deepest = 0;
    for (int k = 0; k < std::lround(20 * period / sim.model.dt); ++k) {
        sim.step();
        const physics::Vec3 a =
            physics::body_pose(sim.model, sim.state, 1).orientation * physics::Vec3::UnitZ();
        deepest = std::max(deepest, std::acos(a.z()) - top.theta);
    }
    TUMBLE_MEASURED(std::abs(deepest / depth - 1), 0.15);
    EXPECT_NEAR(deepest / depth, 1.0, 0.15);
    expect_quoted(kLesson, "nutation_if_let_go", 180 / kPi * depth);
    expect_quoted(kLesson, "nutation_period_if_let_go", 1e3 * period);
}

} // namespace
} // namespace tumble::test
