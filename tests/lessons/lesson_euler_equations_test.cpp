// Lesson 1 (docs/lessons/01-euler-equations.md): the wobbling plate of
// assets/scenes/lessons/wobbling_plate.json, run as the app runs it, turns as Euler's equations
// say. For a body with I1 = I2 (a square plate) and no torque, tau = I dw/dt + w x I w = 0 in the
// body frame reads
//   I1 dw1/dt = (I1 - I3) w3 w2,   I1 dw2/dt = (I3 - I1) w3 w1,   I3 dw3/dt = 0,
// so w3 is constant and (w1, w2) turns about the plate's axis at Omega_b = (I3 - I1) / I1 w3;
// seen from the room the axis turns about the fixed L at |L| / I1 (the regular precession of a
// torque-free symmetric top: Landau and Lifshitz, Mechanics, section 33; Goldstein, Classical
// Mechanics, 3rd ed., section 5.6). The moments come from the box formula here
// (I = m (b^2 + c^2) / 12), not from the model.
#include "lesson_support.h"

#include "physics/state.h"

namespace tumble::test {
namespace {

constexpr const char* kLesson = "01-euler-equations.md";

struct Rates {
    double body, room, worst_l_error;
};

Rates measure(const app::Scene& scene, const physics::Vec3& inertia) {
    app::Simulation sim = lesson_simulation(scene);
    const int plate = 1;
    const auto momentum = [&](const physics::Quat& q, const physics::Vec3& w) {
        return physics::Vec3(q * inertia.cwiseProduct(q.conjugate() * w)); // L = R I R^T w
    };
    const physics::Quat q0 = physics::body_pose(sim.model, sim.state, plate).orientation;
    const physics::Vec3 L0 = momentum(q0, sim.state.w[plate]);
    TurnRates rates(L0);
    double worst = 0;
    const auto steps = static_cast<int>(std::lround(scene.duration / sim.model.dt));
    for (int k = 0; k <= steps; ++k) {
        if (k > 0) sim.step();
        const physics::Quat q = physics::body_pose(sim.model, sim.state, plate).orientation;
        const physics::Vec3 w = sim.state.w[plate];
        rates.add(k * sim.model.dt, q.conjugate() * w, q * physics::Vec3::UnitZ());
        worst = std::max(worst, (momentum(q, w) - L0).norm() / L0.norm());
    }
    return {rates.body(), rates.room(), worst};
}

TEST(Lessons, TheWobblingPlateTurnsAsEulersEquationsSay) {
    const app::Scene scene = lesson_scene("wobbling_plate");
    const physics::BodyDef& plate = scene.bodies[1];
    const physics::Vec3 inertia = box_moments(plate);
    ASSERT_EQ(inertia.x(), inertia.y()) << "the lesson's plate is square";
    const physics::Vec3 wb = plate.orientation.conjugate() * plate.angular_velocity;
    const double i1 = inertia.x(), i3 = inertia.z();
    const double body_rate = (i3 - i1) / i1 * wb.z();
    const double room_rate = std::hypot(i1 * wb.x(), i3 * wb.z()) / i1;

    const Rates r = measure(scene, inertia);
    const double body_error = std::abs(r.body / body_rate - 1);
    const double room_error = std::abs(r.room / room_rate - 1);
    TUMBLE_MEASURED(body_error, 1e-9);
    TUMBLE_MEASURED(room_error, 1e-9);
    TUMBLE_MEASURED(r.worst_l_error, 1e-12);
    EXPECT_LT(body_error, 1e-9); // splitting is exact for a symmetric body: round-off only
    EXPECT_LT(room_error, 1e-9);
    EXPECT_LT(r.worst_l_error, 1e-12); // world L is constant: the transport theorem's point

    expect_quoted(kLesson, "inertia_ratio", i3 / i1);
    expect_quoted(kLesson, "w_turns_in_body", r.body);
    expect_quoted(kLesson, "axis_turns_in_room", r.room);
    expect_quoted(kLesson, "wobble_over_spin", r.room / r.body);
    expect_quoted(kLesson, "wobble_over_w3", r.room / wb.z());
    // The cones' angles: axis to L, tan = I1 w1 / (I3 w3); axis to w, tan = w1 / w3.
    expect_quoted(kLesson, "axis_to_L", 180 / M_PI * std::atan2(i1 * wb.x(), i3 * wb.z()));
    expect_quoted(kLesson, "axis_to_w", 180 / M_PI * std::atan2(wb.x(), wb.z()));
}

// Exercise 1: the same throw of a plate of (almost) no thickness: I3 = 2 I1, so Omega_b = w3 and
// |L| / I1 = sqrt(w1^2 + 4 w3^2); the scene's run with the plate 0.1 mm thick says the same.
TEST(Lessons, AThinPlateWobblesAtTheLimitingRates) {
    app::Scene scene = lesson_scene("wobbling_plate");
    physics::BodyDef& plate = scene.bodies[1];
    plate.shape.half_extents.z() = 0.5e-4;
    const physics::Vec3 inertia = box_moments(plate);
    const physics::Vec3 wb = plate.orientation.conjugate() * plate.angular_velocity;
    const double thin_body = wb.z(), thin_room = std::hypot(wb.x(), 2 * wb.z());
    const Rates r = measure(scene, inertia);
    EXPECT_NEAR(r.body / thin_body, 1.0, 1e-6); // 0.1 mm is thin to 1e-7
    EXPECT_NEAR(r.room / thin_room, 1.0, 1e-6);
    expect_quoted(kLesson, "thin_w_turns_in_body", thin_body);
    expect_quoted(kLesson, "thin_axis_turns_in_room", thin_room);
}

// Exercise 3: an engine without w x I w keeps w fixed in the world, R(t) = exp(t [w]x) R0, so
// L = R I_body R^T w turns about w at |w| with the plate: after one turn, 2 pi / |w|, it is back.
TEST(Lessons, WithoutTheTransportTermLTurnsWithThePlate) {
    const app::Scene scene = lesson_scene("wobbling_plate");
    const physics::BodyDef& plate = scene.bodies[1];
    const physics::Vec3 w = plate.angular_velocity, inertia = box_moments(plate);
    const auto l_at = [&](double t) {
        const physics::Quat q =
            physics::Quat(Eigen::AngleAxisd(t * w.norm(), w.normalized())) * plate.orientation;
        return physics::Vec3(q * inertia.cwiseProduct(q.conjugate() * w));
    };
    const double period = 2 * M_PI / w.norm();
    EXPECT_LT((l_at(period) - l_at(0)).norm(), 1e-12 * l_at(0).norm());
    EXPECT_GT((l_at(period / 2) - l_at(0)).norm(), 0.1 * l_at(0).norm()); // it does move
    expect_quoted(kLesson, "no_transport_L_period", period);
}

} // namespace
} // namespace tumble::test
