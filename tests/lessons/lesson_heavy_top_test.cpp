// Lesson 9 (docs/lessons/09-heavy-top.md): the heavy symmetric top with a fixed tip (Lagrange's
// top; Goldstein, Classical Mechanics, 3rd ed., section 5.7), three of them on the table of
// assets/scenes/lessons/heavy_top.json, against the theory written out here.
//
// With u = cos(theta) (theta the tilt of the axis a from the vertical), I1' = I1 + m d^2 (across
// the axis, about the tip) and I3, three quantities are conserved for a fixed tip:
//   L_3 = I3 w3 (w3 = w . a),   L_z = e_z . L_tip,   E = T + m g d u,
// and with a = I3 w3 / I1', b = L_z / I1', alpha = 2 (E - 1/2 I3 w3^2) / I1', beta = 2 m g d / I1',
//   (du/dt)^2 = f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2,
//   dphi/dt = (b - a u) / (1 - u^2)   (phi: the azimuth of the axis).
// Let go with the axis at rest at u0 (b = a u0, alpha = beta u0), f = beta (u0 - u)(u - u1)(u2 - u)
// with u1 < u0 < 1 < u2 the roots of beta (1 - u^2) = a^2 (u0 - u): the axis nods between u0 and u1
// (nutation), once every T = 4 K(k) / sqrt(beta (u2 - u1)), k^2 = (u0 - u1) / (u2 - u1). Standing
// upright (u = 1) it stays up ("sleeps") when a^2 > 4 beta, i.e. I3^2 w3^2 > 4 I1' m g d.
// The mass properties are the model's (physics/mesh_mass.cpp, checked against slices by
// TopPrecession.*): the theory and the run are independent beyond them.
#include "lesson_support.h"

#include <cmath>
#include <numbers>

namespace tumble::test {
namespace {

constexpr const char* kLesson = "09-heavy-top.md";
constexpr double kPi = std::numbers::pi, kDeg = 180 / kPi;

struct Top {
    double m, d, i1, i3, g; // i1: across the axis, about the tip
};

Top top_of(const physics::Model& model, int b) {
    int k = 0; // the mass-frame axis along the top's own z
    for (int j = 1; j < 3; ++j)
        if (std::abs((model.body_from_mass[b] * physics::Vec3::Unit(j)).z()) >
            std::abs((model.body_from_mass[b] * physics::Vec3::Unit(k)).z()))
            k = j;
    Top t{};
    t.m = model.mass[b];
    t.d = model.com_offset[b].norm();
    t.i3 = model.inertia[b][k];
    t.i1 = model.inertia[b][(k + 1) % 3] + t.m * t.d * t.d;
    t.g = -model.gravity.z();
    return t;
}

// The nutation of a top let go with its axis at rest at tilt theta0, spinning at w3.
struct Nutation {
    double u0, u1, u2, period, mean_rate;
};

Nutation nutation(const Top& t, double theta0, double w3) {
    const double a = t.i3 * w3 / t.i1, beta = 2 * t.m * t.g * t.d / t.i1, u0 = std::cos(theta0);
    // beta u^2 - a^2 u + (a^2 u0 - beta) = 0
    const double disc = std::sqrt(a * a * a * a - 4 * beta * (a * a * u0 - beta));
    Nutation n{u0, (a * a - disc) / (2 * beta), (a * a + disc) / (2 * beta), 0, 0};
    const double k = std::sqrt((n.u0 - n.u1) / (n.u2 - n.u1));
    n.period = 4 * std::comp_ellint_1(k) / std::sqrt(beta * (n.u2 - n.u1));
    // Azimuth turned per period: 2 * integral from u1 to u0 of (dphi/dt) du / (du/dt), with
    // u = u1 + (u0 - u1) sin^2 s, for which du / sqrt((u0 - u)(u - u1)) = 2 ds (no singularity).
    const int steps = 20000;
    double turned = 0;
    for (int i = 0; i < steps; ++i) {
        const double s = (i + 0.5) * (kPi / 2) / steps, sn = std::sin(s);
        const double u = n.u1 + (n.u0 - n.u1) * sn * sn;
        const double phi_dot = a * (n.u0 - u) / (1 - u * u);
        turned += 2 * phi_dot * 2 / std::sqrt(beta * (n.u2 - u)) * (kPi / 2) / steps;
    }
    n.mean_rate = turned / n.period;
    return n;
}

// Energy, L_z about the tip's starting point and L_3 of body b.
struct Invariants {
    double e, lz, l3;
};

Invariants invariants(const app::Simulation& sim, int b, const physics::Vec3& tip) {
    const physics::Model& m = sim.model;
    const physics::State& s = sim.state;
    const physics::Quat q = s.q[b];
    const physics::Vec3 iw = q * m.inertia[b].cwiseProduct(q.conjugate() * s.w[b]);
    const physics::Vec3 a = physics::body_pose(m, s, b).orientation * physics::Vec3::UnitZ();
    const physics::Vec3 l_tip = iw + m.mass[b] * (s.x[b] - tip).cross(s.v[b]);
    return {0.5 * m.mass[b] * s.v[b].squaredNorm() + 0.5 * s.w[b].dot(iw) -
                m.mass[b] * m.gravity.dot(s.x[b]),
            l_tip.z(), iw.dot(a)};
}

TEST(Lessons, TheTopLetGoAtRestNodsBetweenThePredictedTilts) {
    const app::Scene scene = lesson_scene("heavy_top");
    app::Simulation sim = lesson_simulation(scene);
    const int b = body_index(scene, "nutating");
    const Top top = top_of(sim.model, b);
    const physics::Quat q0 = physics::body_pose(sim.model, sim.state, b).orientation;
    const physics::Vec3 a0 = q0 * physics::Vec3::UnitZ();
    const double theta0 = std::acos(a0.z()), w3 = sim.state.w[b].dot(a0);
    ASSERT_LT((sim.state.w[b] - w3 * a0).norm(), 1e-6 * w3) << "let go spinning, axis at rest";
    const Nutation n = nutation(top, theta0, w3);
    const physics::Vec3 tip = physics::body_pose(sim.model, sim.state, b).position;
    const Invariants start = invariants(sim, b, tip);

    // The run: tilt and azimuth at every step, the invariants' worst drift.
    const double h = sim.model.dt;
    const auto steps = static_cast<int>(std::lround(scene.duration / h));
    std::vector<double> t, tilt, azimuth;
    double turned = 0, last = 0, worst_e = 0, worst_lz = 0, worst_l3 = 0, wander = 0;
    for (int k = 0; k <= steps; ++k) {
        if (k > 0) sim.step();
        const physics::Vec3 a =
            physics::body_pose(sim.model, sim.state, b).orientation * physics::Vec3::UnitZ();
        const double az = std::atan2(a.y(), a.x());
        if (k == 0) last = az;
        turned = unwrap(turned, last, az);
        t.push_back(k * h);
        tilt.push_back(std::acos(a.z()));
        azimuth.push_back(turned);
        wander =
            std::max(wander, (physics::body_pose(sim.model, sim.state, b).position - tip).norm());
        const Invariants now = invariants(sim, b, tip);
        worst_e = std::max(worst_e, std::abs(now.e / start.e - 1));
        worst_lz = std::max(worst_lz, std::abs(now.lz / start.lz - 1));
        worst_l3 = std::max(worst_l3, std::abs(now.l3 / start.l3 - 1));
    }
    // Nutation: the deepest tilt of the first nod, and the times of the tilt's minima (the axis
    // back near theta0).
    const double deepest =
        *std::max_element(tilt.begin(), tilt.begin() + long(std::lround(n.period / h)));
    std::vector<double> minima;
    for (std::size_t i = 1; i + 1 < tilt.size(); ++i)
        if (tilt[i] < tilt[i - 1] && tilt[i] <= tilt[i + 1] && i * h > 0.5 * n.period)
            minima.push_back(t[i]);
    ASSERT_GE(minima.size(), 3u);
    // The later nods: the tilt's maxima after the first period.
    double later_min = 1e9, later_max = 0;
    for (std::size_t i = 1; i + 1 < tilt.size(); ++i)
        if (tilt[i] > tilt[i - 1] && tilt[i] >= tilt[i + 1] && t[i] > n.period)
            later_min = std::min(later_min, tilt[i] - theta0),
            later_max = std::max(later_max, tilt[i] - theta0);
    const double period = (minima.back() - minima.front()) / double(minima.size() - 1);
    // The mean precession rate over the whole nutation periods of the run.
    const std::size_t end = std::size_t(std::lround(minima.back() / h));
    const double rate = azimuth[end] / t[end];

    const double amplitude = std::acos(n.u1) - theta0;
    // A contact with friction is not a pivot: the tip creeps by a millimetre or so, and the nods
    // come out within 10 % of the fixed-tip theory, the period within 2 %, the mean rate within 2
    // %.
    TUMBLE_MEASURED(std::abs(deepest - theta0 - amplitude) / amplitude, 0.1);
    TUMBLE_MEASURED(std::abs(period / n.period - 1), 0.02);
    TUMBLE_MEASURED(std::abs(rate / n.mean_rate - 1), 0.02);
    EXPECT_LT(std::abs(deepest - theta0 - amplitude) / amplitude, 0.1);
    EXPECT_LT(std::abs(period / n.period - 1), 0.02);
    EXPECT_LT(std::abs(rate / n.mean_rate - 1), 0.02);
    // The fixed-tip invariants, about the tip's starting point: L_3 holds (no torque along the
    // axis, wherever the tip is), E and L_z move with the tip's creep.
    TUMBLE_MEASURED(1000 * wander, 3.0);
    TUMBLE_MEASURED(worst_e, 5e-3);
    TUMBLE_MEASURED(worst_lz, 5e-2);
    TUMBLE_MEASURED(worst_l3, 1e-3);
    EXPECT_LT(wander, 3e-3); // m
    EXPECT_LT(worst_e, 5e-3);
    EXPECT_LT(worst_lz, 5e-2);
    EXPECT_LT(worst_l3, 1e-3);

    // The fast-top estimates: amplitude 2 I1' m g d sin(theta0) / (I3 w3)^2, frequency I3 w3 / I1'.
    const double l3 = top.i3 * w3;
    const double fast_amplitude = 2 * top.i1 * top.m * top.g * top.d * std::sin(theta0) / (l3 * l3);
    const double fast_period = 2 * kPi * top.i1 / l3;

    expect_quoted(kLesson, "mass", top.m);
    expect_quoted(kLesson, "tip_to_centre", 100 * top.d);
    expect_quoted(kLesson, "i1_tip", 1e6 * top.i1);
    expect_quoted(kLesson, "i3", 1e6 * top.i3);
    expect_quoted(kLesson, "nutating_w3", w3);
    expect_quoted(kLesson, "nutation_amplitude", kDeg * amplitude);
    expect_quoted(kLesson, "measured_amplitude", kDeg * (deepest - theta0));
    expect_quoted(kLesson, "later_nods_min", kDeg * later_min);
    expect_quoted(kLesson, "later_nods_max", kDeg * later_max);
    // The energy a nod trades: m g d (cos(theta0) - cos(theta0 + amplitude)), against the whole.
    const double nod_energy = top.m * top.g * top.d * (n.u0 - n.u1);
    expect_quoted(kLesson, "nod_energy_fraction", 100 * nod_energy / start.e);
    expect_quoted(kLesson, "fast_amplitude", kDeg * fast_amplitude);
    expect_quoted(kLesson, "nutation_period", 1e3 * n.period);
    expect_quoted(kLesson, "measured_period", 1e3 * period);
    expect_quoted(kLesson, "fast_period", 1e3 * fast_period);
    expect_quoted(kLesson, "mean_rate", n.mean_rate);
    expect_quoted(kLesson, "measured_rate", rate);
    // Lesson 5's steady precession at the same tilt and spin: the slow root of
    // I1' cos(theta) W^2 - I3 w3 W + m g d = 0.
    const double c = top.i1 * std::cos(theta0);
    const double steady = (l3 - std::sqrt(l3 * l3 - 4 * c * top.m * top.g * top.d)) / (2 * c);
    expect_quoted(kLesson, "steady_rate", steady);
    expect_quoted(kLesson, "tip_wander", 1000 * wander);
    expect_quoted(kLesson, "energy_drift", 100 * worst_e);
    expect_quoted(kLesson, "lz_drift", 100 * worst_lz);
    expect_quoted(kLesson, "l3_drift", 100 * worst_l3);
    // A gyroscope with its axle horizontal (cos theta = 0): the steady-precession equation
    // I1' cos(theta) W^2 - I3 w3 W + m g d = 0 is linear, W = m g d / (I3 w3) exactly.
    expect_quoted(kLesson, "gyroscope_rate", top.m * top.g * top.d / l3);
}

// Standing upright: I3^2 w3^2 > 4 I1' m g d, or it falls.
TEST(Lessons, TheFastTopSleepsAndTheSlowOneFalls) {
    const app::Scene scene = lesson_scene("heavy_top");
    app::Simulation sim = lesson_simulation(scene);
    const int fast = body_index(scene, "sleeping"), slow = body_index(scene, "falling");
    const Top top = top_of(sim.model, fast);
    const double critical = std::sqrt(4 * top.i1 * top.m * top.g * top.d) / top.i3;
    const auto spin = [&](int b) {
        const physics::Vec3 a =
            physics::body_pose(sim.model, sim.state, b).orientation * physics::Vec3::UnitZ();
        return sim.state.w[b].dot(a);
    };
    const double fast_w3 = spin(fast), slow_w3 = spin(slow);
    ASSERT_GT(fast_w3, critical);
    ASSERT_LT(slow_w3, critical);
    double fast_worst = 0, slow_fell_at = -1;
    const auto steps = static_cast<int>(std::lround(scene.duration / sim.model.dt));
    for (int k = 1; k <= steps; ++k) {
        sim.step();
        const auto tilt = [&](int b) {
            return std::acos(
                (physics::body_pose(sim.model, sim.state, b).orientation * physics::Vec3::UnitZ())
                    .z());
        };
        fast_worst = std::max(fast_worst, tilt(fast));
        if (slow_fell_at < 0 && tilt(slow) > 30 / kDeg) slow_fell_at = k * sim.model.dt;
    }
    TUMBLE_MEASURED(kDeg * fast_worst, 3.0);
    EXPECT_LT(kDeg * fast_worst, 3.0); // degrees: it sleeps
    EXPECT_GT(slow_fell_at, 0.0);      // it fell past 30 degrees
    expect_quoted(kLesson, "critical_w3", critical);
    expect_quoted(kLesson, "sleeping_w3", fast_w3);
    expect_quoted(kLesson, "falling_w3", slow_w3);
    expect_quoted(kLesson, "sleeping_worst_tilt", kDeg * fast_worst);
    expect_quoted(kLesson, "falling_time", slow_fell_at);
}

} // namespace
} // namespace tumble::test
