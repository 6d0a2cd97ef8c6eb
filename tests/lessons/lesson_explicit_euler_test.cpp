// Lesson 2 (docs/lessons/02-explicit-euler.md): the course notes' explicit Euler loops on
// MuJoCo's tumbling box (assets/scenes/lessons/euler_box.json), run as the app runs them, change
// the energy at the rate derived to first order in h, and the change halves with h.
//
// Torque-free, in the body frame: w_b = R^T w, m = I w_b, and Euler's equations are dm/dt = g with
// g = m x w_b (tau = I dw/dt + w x I w = 0). Write E = 1/2 w_b . I w_b.
//  - (x, v, R, w) loop, physics/integrator_euler.cpp: w' = w + h I_w^-1 (-w x I_w w) is w_b + h
//  I^-1 g
//    in the old body frame; R' = Gram-Schmidt(R + h [w]x R) = R GS(1 + h [w_b]x), and Gram-Schmidt
//    on the columns in the order x, y, z turns by exp([h w_b + h^2 d]x) + O(h^3) with
//    d = 1/2 (-w2 w3, w1 w3, -w1 w2) (expand the normalised columns to h^2 and match them with
//    1 + [phi]x + [phi]x^2 / 2). Then w_b' = R'^T w' = w_b + h I^-1 g - h^2 (d x w_b + w_b x I^-1
//    g) and, using g . w_b = 0 and (w_b x I^-1 g) . m = g . I^-1 g,
//        2 E' - 2 E = h^2 (2 d . g - g . I^-1 g) + O(h^3)
//    (integrator_euler.cpp derives the second term; the first is the Gram-Schmidt term it names).
//  - (x, P, q, L) loop, physics/integrator_euler_momentum.cpp, and symplectic_euler: the body-frame
//    momentum steps as m' = m + h g + O(h^2 terms orthogonal to I^-1 m), so
//        2 E' - 2 E = h^2 g . I^-1 g + O(h^3)   (exactly, with no O(h^3), for symplectic_euler).
// Per unit time: (1/E) dE/dt = h (2 d . g - g . I^-1 g) / (2 E) and h g . I^-1 g / (2 E), first
// order in h. The moments come from the box formula here, not from the model.
#include "lesson_support.h"

namespace tumble::test {
namespace {

constexpr const char* kLesson = "02-explicit-euler.md";

struct Box {
    physics::Vec3 inertia, wb;
};

Box lesson_box(const app::Scene& scene) {
    const physics::BodyDef& b = scene.bodies[1];
    const physics::Vec3 s = 2.0 * b.shape.half_extents;
    return {physics::Vec3(b.mass * (s.y() * s.y() + s.z() * s.z()) / 12,
                          b.mass * (s.x() * s.x() + s.z() * s.z()) / 12,
                          b.mass * (s.x() * s.x() + s.y() * s.y()) / 12),
            b.orientation.conjugate() * b.angular_velocity};
}

double energy(const app::Simulation& sim, const physics::Vec3& inertia) {
    const physics::Quat q = physics::body_pose(sim.model, sim.state, 1).orientation;
    const physics::Vec3 wb = q.conjugate() * sim.state.w[1];
    return 0.5 * wb.dot(inertia.cwiseProduct(wb));
}

// The first-order relative rates at t = 0: {euler, gain of euler_momentum and symplectic_euler},
// per unit h.
std::pair<double, double> predicted_rates(const Box& box) {
    const physics::Vec3 w = box.wb, m = box.inertia.cwiseProduct(w), g = m.cross(w);
    const physics::Vec3 d = 0.5 * physics::Vec3(-w.y() * w.z(), w.x() * w.z(), -w.x() * w.y());
    const double g_g = g.dot(g.cwiseQuotient(box.inertia)), e = 0.5 * w.dot(m);
    return {(2 * d.dot(g) - g_g) / (2 * e), g_g / (2 * e)};
}

// |L|, from the body frame: |I w_b|.
double momentum(const app::Simulation& sim, const physics::Vec3& inertia) {
    const physics::Quat q = physics::body_pose(sim.model, sim.state, 1).orientation;
    return inertia.cwiseProduct(q.conjugate() * sim.state.w[1]).norm();
}

// (1/E) dE/dt over the first step, and E(t)/E(0) at t = `at`; |L(t)| / |L(0)| in `l_ratio`.
std::pair<double, double> measured(const app::Scene& scene, const Box& box,
                                   const std::string& integrator, double h, double at,
                                   double* l_ratio = nullptr) {
    app::Simulation sim = lesson_simulation(scene, integrator_named(integrator), h);
    const double e0 = energy(sim, box.inertia), l0 = momentum(sim, box.inertia);
    sim.step();
    const double first = (energy(sim, box.inertia) / e0 - 1) / h;
    for (int k = 1; k < std::lround(at / h); ++k) sim.step();
    if (l_ratio) *l_ratio = momentum(sim, box.inertia) / l0;
    return {first, energy(sim, box.inertia) / e0};
}

TEST(Lessons, ExplicitEulerChangesTheEnergyAtTheRateDerivedToFirstOrder) {
    const app::Scene scene = lesson_scene("euler_box");
    const Box box = lesson_box(scene);
    const double h = scene.world.dt;
    const auto [euler_rate, gain_rate] = predicted_rates(box);
    expect_quoted(kLesson, "euler_rate_predicted", 100 * h * euler_rate);
    expect_quoted(kLesson, "gain_rate_predicted", 100 * h * gain_rate);

    double euler_l = 0, momentum_l = 0, symplectic_l = 0;
    const auto [euler_first, euler_5s] = measured(scene, box, "euler", h, 5.0, &euler_l);
    const auto [momentum_first, momentum_5s] =
        measured(scene, box, "euler_momentum", h, 5.0, &momentum_l);
    const auto [symplectic_first, symplectic_5s] =
        measured(scene, box, "symplectic_euler", h, 5.0, &symplectic_l);
    // |L|: the (x, P, q, L) loop adds h tau = 0 to L every step, so it keeps L to round-off.
    TUMBLE_MEASURED(std::abs(momentum_l - 1), 1e-13);
    EXPECT_LT(std::abs(momentum_l - 1), 1e-13);
    expect_quoted(kLesson, "euler_L_5s", euler_l);
    expect_quoted(kLesson, "euler_momentum_L_5s", momentum_l);
    expect_quoted(kLesson, "symplectic_euler_L_5s", symplectic_l);
    // O(h) relative: h |w| = 0.037 here.
    const double euler_off = std::abs(euler_first / (h * euler_rate) - 1);
    const double momentum_off = std::abs(momentum_first / (h * gain_rate) - 1);
    const double symplectic_off = std::abs(symplectic_first / (h * gain_rate) - 1);
    TUMBLE_MEASURED(euler_off, 0.02);
    TUMBLE_MEASURED(momentum_off, 0.02);
    TUMBLE_MEASURED(symplectic_off, 1e-9);
    EXPECT_LT(euler_off, 0.02);
    EXPECT_LT(momentum_off, 0.02);
    EXPECT_LT(symplectic_off, 1e-9); // 2 E' = 2 E + h^2 g . I^-1 g holds exactly
    expect_quoted(kLesson, "euler_rate_measured", 100 * euler_first);
    expect_quoted(kLesson, "euler_momentum_rate_measured", 100 * momentum_first);
    expect_quoted(kLesson, "euler_5s", euler_5s);
    expect_quoted(kLesson, "euler_momentum_5s", momentum_5s);
    expect_quoted(kLesson, "symplectic_euler_5s", symplectic_5s);

    // First order: at h/2 the loss over the first second is half as large (in log E; over 5 s,
    // where 15 % is lost, the trajectory itself has moved too far for the ratio to be 2).
    const double euler_1s = measured(scene, box, "euler", h, 1.0).second;
    const double euler_1s_half = measured(scene, box, "euler", h / 2, 1.0).second;
    const double halving = std::log(euler_1s) / std::log(euler_1s_half);
    TUMBLE_MEASURED(std::abs(halving - 2), 0.1);
    EXPECT_NEAR(halving, 2.0, 0.1);
    expect_quoted(kLesson, "euler_1s", euler_1s);
    expect_quoted(kLesson, "euler_1s_half_step", euler_1s_half);

    // Exercise 1: at 2h, first order doubles the loss in log E: E / E0 about euler_1s^2.
    const double euler_1s_double = measured(scene, box, "euler", 2 * h, 1.0).second;
    const double predicted = euler_1s * euler_1s;
    TUMBLE_MEASURED(std::abs(std::log(euler_1s_double) / std::log(predicted) - 1), 0.1);
    EXPECT_NEAR(std::log(euler_1s_double) / std::log(predicted), 1.0, 0.1);
    expect_quoted(kLesson, "euler_1s_double_step_predicted", predicted);
    expect_quoted(kLesson, "euler_1s_double_step", euler_1s_double);
}

// Exercise 3: spun about one principal axis, g = L_b x w_b = 0: Euler's equations say nothing
// changes, and every first-order term of the drift vanishes (d . g = g . I^-1 g = 0). The course
// loop keeps the energy to round-off.
TEST(Lessons, ABoxSpunAboutOneAxisKeepsItsEnergyInTheCourseLoop) {
    app::Scene scene = lesson_scene("euler_box");
    scene.bodies[1].angular_velocity = scene.bodies[1].orientation * physics::Vec3(0, 0, 3);
    const Box box = lesson_box(scene);
    const double e5 = measured(scene, box, "euler", scene.world.dt, 5.0).second;
    TUMBLE_MEASURED(std::abs(e5 - 1), 1e-12);
    EXPECT_LT(std::abs(e5 - 1), 1e-12);
}

} // namespace
} // namespace tumble::test
