// Lesson 11 (docs/lessons/11-dissipation.md): the major-axis rule. A body that loses energy while
// keeping its angular momentum ends spinning about its axis of largest moment, where the energy
// |L|^2 / (2 I) is least. The "damped" satellite of assets/scenes/lessons/explorer.json shares a
// viscous damper (physics/damper.h: torque c (w_rotor - w)) with a spherical rotor of moment J;
// spun about its long axis, the axis of least moment, it turns end over end as Explorer 1 did.
//  - Momentum: the damper's torques are equal and opposite, so L = I_w w + J s is conserved.
//  - The end: satellite and rotor turning together about the satellite's largest axis, with
//    E = |L|^2 / (2 (I_max + J)).
//  - The start: linearising the satellite's and the rotor's equations in the satellite frame,
//      I dw/dt = -w x I w + c (s - w),   ds/dt = (c / J) (w - s) - w x s,
//    about the spin w = s = W e3 gives the growth rate of the wobble: the largest real part of the
//    Jacobian's eigenvalues, computed here by finite differences of these equations (no Tumble
//    code) and Eigen's eigenvalue solver.
// Then the "rigid" satellite, without a damper, keeps its small wobble for ever under splitting;
// under implicit_gyro (backward Euler on the gyroscopic term, Bullet's default) the wobble dies:
// backward Euler multiplies each oscillation of frequency W_n by 1 / (1 + i h W_n), so its
// amplitude decays at ln(1 + h^2 W_n^2) / (2 h) per second, W_n = W sqrt((I1 - I3)(I2 - I3) /
// (I1 I2)) the wobble's frequency in the body: numerical damping that keeps the minor-axis spin,
// which a real damper would overturn.
#include "lesson_support.h"

#include <Eigen/Eigenvalues>

#include <numbers>

namespace tumble::test {
namespace {

constexpr const char* kLesson = "11-dissipation.md";
constexpr double kDeg = 180 / std::numbers::pi;

using Vec6 = Eigen::Matrix<double, 6, 1>;

// The growth rate of a wobble about the spin W e3 with the damper (c, J), body moments `i`.
double growth_rate(const physics::Vec3& i, double j, double c, double w) {
    const auto f = [&](const Vec6& y) {
        const physics::Vec3 om = y.head<3>(), s = y.tail<3>();
        Vec6 out;
        out.head<3>() = (c * (s - om) - om.cross(i.cwiseProduct(om))).cwiseQuotient(i);
        out.tail<3>() = c / j * (om - s) - om.cross(s);
        return out;
    };
    Vec6 y0;
    y0 << 0, 0, w, 0, 0, w;
    Eigen::Matrix<double, 6, 6> jac;
    for (int k = 0; k < 6; ++k) {
        Vec6 dy = Vec6::Zero();
        dy[k] = 1e-6;
        jac.col(k) = (f(y0 + dy) - f(y0 - dy)) / 2e-6;
    }
    return Eigen::EigenSolver<Eigen::Matrix<double, 6, 6>>(jac).eigenvalues().real().maxCoeff();
}

struct Trace {
    std::vector<double> t, nutation; // angle of the satellite's long axis from its L (or the total)
    double l_drift = 0, e_start = 0, e_end = 0, l_total = 0;
    bool energy_rose = false;
};

// The run of `scene` with `integrator`, following body `name`; with `total`, L is the scene's
// (satellite and rotor), else the body's own.
Trace run(const app::Scene& scene, const std::string& name, bool total,
          std::optional<physics::Integrator> integrator = {}, std::optional<double> dt = {}) {
    app::Simulation sim = lesson_simulation(scene, integrator, dt);
    const int b = body_index(scene, name), r = body_index(scene, "rotor");
    const auto spin_l = [&](int i) {
        const physics::Quat q = sim.state.q[i];
        return physics::Vec3(q * sim.model.inertia[i].cwiseProduct(q.conjugate() * sim.state.w[i]));
    };
    const auto energy = [&] {
        return 0.5 * sim.state.w[b].dot(spin_l(b)) + 0.5 * sim.state.w[r].dot(spin_l(r));
    };
    const physics::Vec3 l0 = total ? physics::Vec3(spin_l(b) + spin_l(r)) : spin_l(b);
    Trace out;
    out.e_start = energy();
    out.l_total = l0.norm();
    double last_e = out.e_start;
    const double h = sim.model.dt;
    const auto steps = static_cast<int>(std::lround(scene.duration / h));
    for (int k = 0; k <= steps; ++k) {
        if (k > 0) sim.step();
        const physics::Vec3 l = total ? physics::Vec3(spin_l(b) + spin_l(r)) : spin_l(b);
        const physics::Vec3 axis =
            physics::body_pose(sim.model, sim.state, b).orientation * physics::Vec3::UnitZ();
        out.t.push_back(k * h);
        const double a = angle_between(axis, l);
        out.nutation.push_back(std::min(a, M_PI - a)); // the axis' line, either end
        if (total) out.l_drift = std::max(out.l_drift, (l - l0).norm() / l0.norm());
        const double e = energy();
        out.energy_rose |= e > last_e * (1 + 1e-14);
        last_e = e;
    }
    out.e_end = last_e;
    return out;
}

// Slope of ln(nutation) over [from, to] s.
double log_slope(const Trace& r, double from, double to) {
    std::vector<double> t, y;
    for (std::size_t k = 0; k < r.t.size(); ++k)
        if (r.t[k] >= from && r.t[k] <= to)
            t.push_back(r.t[k]), y.push_back(std::log(r.nutation[k]));
    return slope(t, y);
}

TEST(Lessons, TheDampedSatelliteEndsTurningEndOverEnd) {
    const app::Scene scene = lesson_scene("explorer");
    const int b = body_index(scene, "damped"), rotor = body_index(scene, "rotor");
    const physics::Vec3 i = box_moments(scene.bodies[b]);
    const double j = 0.4 * scene.bodies[rotor].mass * std::pow(scene.bodies[rotor].shape.radius, 2);
    ASSERT_EQ(scene.world.dampers.size(), 1u);
    const double c = scene.world.dampers[0].c;
    const double w =
        (scene.bodies[b].orientation.conjugate() * scene.bodies[b].angular_velocity).z();
    ASSERT_EQ(i.minCoeff(), i.z()) << "spun about the long axis, the least moment";

    const Trace r = run(scene, "damped", true);
    TUMBLE_MEASURED(r.l_drift, 1e-12);
    EXPECT_LT(r.l_drift, 1e-12); // the damper's torques cancel: L exactly
    EXPECT_FALSE(r.energy_rose); // and energy only ever leaves
    const double e_final = r.l_total * r.l_total / (2 * (i.maxCoeff() + j));
    TUMBLE_MEASURED(std::abs(r.e_end / e_final - 1), 1e-3);
    EXPECT_NEAR(r.e_end / e_final, 1.0, 1e-3);
    EXPECT_GT(r.nutation.back(), 85 / kDeg); // the long axis ends across L

    const double lambda = growth_rate(i, j, c, w), measured = log_slope(r, 1.0, 8.0);
    TUMBLE_MEASURED(std::abs(measured / lambda - 1), 0.05);
    EXPECT_NEAR(measured / lambda, 1.0, 0.05);
    std::size_t k45 = 0;
    while (r.nutation[k45] < 45 / kDeg) ++k45;

    constexpr double kgcm2 = 1e4;
    expect_quoted(kLesson, "I_long", kgcm2 * i.z());
    expect_quoted(kLesson, "I_max", kgcm2 * i.maxCoeff());
    expect_quoted(kLesson, "rotor_J", kgcm2 * j);
    expect_quoted(kLesson, "start_energy", 1e3 * r.e_start);
    expect_quoted(kLesson, "final_energy", 1e3 * e_final);
    expect_quoted(kLesson, "measured_final_energy", 1e3 * r.e_end);
    expect_quoted(kLesson, "energy_kept", e_final / r.e_start);
    expect_quoted(kLesson, "growth_rate", lambda);
    expect_quoted(kLesson, "measured_growth_rate", measured);
    expect_quoted(kLesson, "start_nutation", kDeg * r.nutation.front());
    expect_quoted(kLesson, "time_to_45", r.t[k45]);
    expect_quoted(kLesson, "final_nutation", kDeg * r.nutation.back());
    // Exercise: the energy the end state keeps, without the rotor's share (J -> 0):
    // I_min / I_max of the start.
    expect_quoted(kLesson, "energy_kept_small_rotor", i.minCoeff() / i.maxCoeff());
}

TEST(Lessons, ImplicitGyroDampsTheWobbleAtTheRateBackwardEulerPredicts) {
    const app::Scene scene = lesson_scene("explorer");
    const int b = body_index(scene, "rigid");
    const physics::Vec3 i = box_moments(scene.bodies[b]);
    const double w =
        (scene.bodies[b].orientation.conjugate() * scene.bodies[b].angular_velocity).z();
    const double wn = w * std::sqrt((i.x() - i.z()) * (i.y() - i.z()) / (i.x() * i.y()));
    const auto predicted = [&](double h) { return std::log(1 + h * h * wn * wn) / (2 * h); };
    const double h = scene.world.dt;

    const Trace kept = run(scene, "rigid", false); // splitting: the wobble stays
    const auto [lo, hi] = std::minmax_element(kept.nutation.begin(), kept.nutation.end());
    TUMBLE_MEASURED(*hi - *lo, 1e-3 * *hi);
    EXPECT_LT(*hi - *lo, 0.05 * *hi); // it breathes with I1 != I2 but neither grows nor dies

    const physics::Integrator ig = integrator_named("implicit_gyro");
    const double rate = -log_slope(run(scene, "rigid", false, ig), 2.0, 20.0);
    const double rate_half = -log_slope(run(scene, "rigid", false, ig, h / 2), 2.0, 20.0);
    TUMBLE_MEASURED(std::abs(rate / predicted(h) - 1), 0.03);
    TUMBLE_MEASURED(std::abs(rate_half / predicted(h / 2) - 1), 0.03);
    EXPECT_NEAR(rate / predicted(h), 1.0, 0.03);
    EXPECT_NEAR(rate_half / predicted(h / 2), 1.0, 0.03);
    expect_quoted(kLesson, "wobble_frequency", wn);
    expect_quoted(kLesson, "implicit_decay_predicted", predicted(h));
    expect_quoted(kLesson, "implicit_decay_measured", rate);
    expect_quoted(kLesson, "implicit_decay_half_step", rate_half);
    expect_quoted(kLesson, "rigid_nutation", kDeg * kept.nutation.front());
}

} // namespace
} // namespace tumble::test
