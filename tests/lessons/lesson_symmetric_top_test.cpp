// Lesson 8 (docs/lessons/08-symmetric-top.md): the torque-free symmetric top, a rod (prolate,
// I3 < I1) and a plate (oblate, I3 > I1) of assets/scenes/lessons/symmetric_tops.json thrown with
// the same w_b = (w1, 0, w3). With I1 = I2, Euler's equations keep w3 and turn (w1, w2) about the
// axis a at Omega_b = (I3 - I1) / I1 w3 (seen from the body), while a goes round the fixed L at
// |L| / I1 (seen from the room): w = L / I1 + (1 - I3 / I1) w3 a (Landau and Lifshitz section 33,
// Goldstein section 5.6). So a, w and L stay in one plane at fixed angles:
//   tan(theta_w) = w1 / w3 (axis to w: the body cone),
//   tan(theta_L) = I1 w1 / (I3 w3) (axis to L),
//   |theta_L - theta_w| (L to w: the space cone).
// Then Earth, from its dynamical flattening H = (C - A) / C (IERS Conventions 2010, Table 1.1):
// the free wobble of a rigid Earth takes A / (C - A) = (1 - H) / H sidereal days.
#include "lesson_support.h"

#include <numbers>

namespace tumble::test {
namespace {

constexpr const char* kLesson = "08-symmetric-top.md";
constexpr double kDeg = 180 / std::numbers::pi;

struct Predicted {
    double theta_w, theta_l, body_rate, room_rate;
};

Predicted predict(const app::Scene& scene, int b) {
    const physics::Vec3 inertia = box_moments(scene.bodies[b]);
    const physics::Vec3 w =
        scene.bodies[b].orientation.conjugate() * scene.bodies[b].angular_velocity;
    const double i1 = inertia.x(), i3 = inertia.z(), w1 = std::hypot(w.x(), w.y()), w3 = w.z();
    return {std::atan2(w1, w3), std::atan2(i1 * w1, i3 * w3), (i3 - i1) / i1 * w3,
            std::hypot(i1 * w1, i3 * w3) / i1};
}

struct Measured {
    double theta_w = 0, theta_l = 0, space = 0, body_rate = 0, room_rate = 0;
    double worst_angle_change = 0; // rad: the cones' angles stay fixed
    double worst_coplanar = 0;     // |a . (w x L)| / (|w| |L|): a, w, L in one plane
};

Measured measure(const app::Scene& scene, int b) {
    app::Simulation sim = lesson_simulation(scene);
    const physics::Vec3 inertia = box_moments(scene.bodies[b]);
    const auto angular_momentum = [&](const physics::Quat& q, const physics::Vec3& w) {
        return physics::Vec3(q * inertia.cwiseProduct(q.conjugate() * w));
    };
    physics::Quat q = physics::body_pose(sim.model, sim.state, b).orientation;
    const physics::Vec3 l0 = angular_momentum(q, sim.state.w[b]);
    const auto angle = [](const physics::Vec3& x, const physics::Vec3& y) {
        return angle_between(x, y);
    };
    Measured m;
    TurnRates rates(l0);
    const auto steps = static_cast<int>(std::lround(scene.duration / sim.model.dt));
    for (int k = 0; k <= steps; ++k) {
        if (k > 0) sim.step();
        q = physics::body_pose(sim.model, sim.state, b).orientation;
        const physics::Vec3 w = sim.state.w[b], a = q * physics::Vec3::UnitZ(),
                            wb = q.conjugate() * w;
        const physics::Vec3 l = angular_momentum(q, w);
        const double tw = angle(a, w), tl = angle(a, l), sp = angle(l, w);
        if (k == 0) m.theta_w = tw, m.theta_l = tl, m.space = sp;
        m.worst_angle_change = std::max({m.worst_angle_change, std::abs(tw - m.theta_w),
                                         std::abs(tl - m.theta_l), std::abs(sp - m.space)});
        m.worst_coplanar =
            std::max(m.worst_coplanar, std::abs(a.dot(w.cross(l))) / (w.norm() * l.norm()));
        rates.add(k * sim.model.dt, wb, a);
    }
    m.body_rate = rates.body();
    m.room_rate = rates.room();
    return m;
}

TEST(Lessons, RodAndPlateTurnOnTheirBodyAndSpaceCones) {
    const app::Scene scene = lesson_scene("symmetric_tops");
    for (const char* name : {"rod", "plate"}) {
        SCOPED_TRACE(name);
        const int b = body_index(scene, name);
        const physics::Vec3 inertia = box_moments(scene.bodies[b]);
        ASSERT_EQ(inertia.x(), inertia.y()) << "a symmetric top";
        const Predicted p = predict(scene, b);
        const Measured m = measure(scene, b);
        TUMBLE_MEASURED(m.worst_angle_change, 1e-9);
        TUMBLE_MEASURED(m.worst_coplanar, 1e-9);
        EXPECT_LT(m.worst_angle_change, 1e-9); // splitting is exact for a symmetric body
        EXPECT_LT(m.worst_coplanar, 1e-9);
        EXPECT_NEAR(m.theta_w, p.theta_w, 1e-12);
        EXPECT_NEAR(m.theta_l, p.theta_l, 1e-12);
        EXPECT_NEAR(m.space, std::abs(p.theta_l - p.theta_w), 1e-12);
        EXPECT_NEAR(m.body_rate / p.body_rate, 1.0, 1e-9);
        EXPECT_NEAR(m.room_rate / p.room_rate, 1.0, 1e-9);
        const std::string n(name);
        expect_quoted(kLesson, n + "_inertia_ratio", inertia.z() / inertia.x());
        expect_quoted(kLesson, n + "_body_cone", kDeg * m.theta_w);
        expect_quoted(kLesson, n + "_axis_to_L", kDeg * m.theta_l);
        expect_quoted(kLesson, n + "_space_cone", kDeg * m.space);
        expect_quoted(kLesson, n + "_body_rate", m.body_rate);
        expect_quoted(kLesson, n + "_room_rate", m.room_rate);
    }
    // The quoted keys, literally (tests/lessons/lesson_structure_test.cpp looks for each):
    // "rod_inertia_ratio" "rod_body_cone" "rod_axis_to_L" "rod_space_cone" "rod_body_rate"
    // "rod_room_rate" "plate_inertia_ratio" "plate_body_cone" "plate_axis_to_L"
    // "plate_space_cone" "plate_body_rate" "plate_room_rate"
}

// A rigid Earth: Euler's free wobble from H, against the observed Chandler period.
TEST(Lessons, ARigidEarthWouldWobbleInAboutTenMonths) {
    const double h = 3.2737949e-3; // (C - A) / C, IERS Conventions (2010), Table 1.1
    const double c_minus_a_over_a = h / (1 - h);
    const double sidereal_day = 86164.0905 / 86400; // in days
    const double sidereal_days = 1 / c_minus_a_over_a;
    const double days = sidereal_days * sidereal_day;
    const double chandler = 433; // days, observed (about 14 months)
    expect_quoted(kLesson, "earth_c_minus_a_over_a", 1e3 * c_minus_a_over_a);
    expect_quoted(kLesson, "euler_period_sidereal_days", sidereal_days);
    expect_quoted(kLesson, "euler_period_days", days);
    expect_quoted(kLesson, "chandler_over_euler", chandler / days);
    // Exercise: a plate's wobble (the room rate) against its spin w3 in the limit of a thin plate
    // and a small tilt: |L| / I1 -> 2 w3, Omega_b -> w3.
    const double i3_over_i1 = 2.0, tilt = 1e-6;
    const double room = std::hypot(tilt, i3_over_i1), body = (i3_over_i1 - 1);
    expect_quoted(kLesson, "thin_plate_room_over_body", room / body);
}

} // namespace
} // namespace tumble::test
