// The viscous rotary damper (physics/damper.h): torque c (w_B - w_A) on A and the opposite on B.
//  - Two spheres (isotropic, I_A, I_B): the relative spin u = w_B - w_A obeys du/dt = -c (1/I_A +
//    1/I_B) u exactly (nothing else turns them), so u(t) = u0 exp(-c (1/I_A + 1/I_B) t) and the
//    common momentum I_A w_A + I_B w_B stays: closed forms written here.
//  - A sphere damped against a static body: w(t) = w0 exp(-c t / I).
//  - Two tumbling boxes: the total angular momentum to round-off over many steps, and the kinetic
//    energy never rising (the damper's flow over a step is exact for the coupling, and
//    dissipative; the integrator's own energy error aside, splitting keeps the free motion's).
#include "physics/build.h"
#include "physics/diagnostics.h"
#include "physics/step.h"

#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::physics {
namespace {

BodyDef sphere(double radius, double mass, const Vec3& at, const Vec3& w) {
    BodyDef b;
    b.shape = Shape::sphere(radius);
    b.mass = mass;
    b.position = at;
    b.angular_velocity = w;
    return b;
}

WorldDef free_world(double dt, Integrator integrator = Integrator::Splitting) {
    WorldDef w;
    w.gravity = Vec3::Zero();
    w.dt = dt;
    w.integrator = integrator;
    return w;
}

TEST(Damper, TwoSpheresShareTheirSpinExponentially) {
    WorldDef world = free_world(0.01);
    world.dampers = {{0, 1, 0.05}};
    const std::vector<BodyDef> bodies = {sphere(0.1, 2.0, Vec3(0, 0, 0), Vec3(0, 0, 10)),
                                         sphere(0.2, 1.0, Vec3(1, 0, 0), Vec3(3, 0, 0))};
    const Model m = build_model(world, bodies);
    ASSERT_TRUE(m.passes.dampers);
    State s = initial_state(m, bodies);
    const double ia = 0.4 * 2.0 * 0.01, ib = 0.4 * 1.0 * 0.04;
    const Vec3 u0 = s.w[1] - s.w[0], p0 = ia * s.w[0] + ib * s.w[1];
    double worst = 0, worst_p = 0;
    for (int k = 1; k <= 500; ++k) {
        step(m, s);
        const double t = k * world.dt;
        const Vec3 u = u0 * std::exp(-0.05 * (1 / ia + 1 / ib) * t);
        worst = std::max(worst, (s.w[1] - s.w[0] - u).norm() / u0.norm());
        worst_p = std::max(worst_p, (ia * s.w[0] + ib * s.w[1] - p0).norm() / p0.norm());
    }
    TUMBLE_MEASURED(worst, 1e-12);
    TUMBLE_MEASURED(worst_p, 1e-14);
    EXPECT_LT(worst, 1e-12); // exact over each step: round-off only
    EXPECT_LT(worst_p, 1e-14);
}

TEST(Damper, AgainstAStaticBodyItBrakesTheSpin) {
    WorldDef world = free_world(0.02);
    BodyDef wall;
    wall.shape = Shape::box(Vec3(0.1, 0.1, 0.1));
    wall.motion = Motion::Static;
    wall.position = Vec3(5, 0, 0);
    world.dampers = {{1, 0, 0.01}};
    const std::vector<BodyDef> bodies = {wall, sphere(0.1, 1.0, Vec3::Zero(), Vec3(0, 2, 7))};
    const Model m = build_model(world, bodies);
    State s = initial_state(m, bodies);
    const double i = 0.4 * 0.01;
    const Vec3 w0 = s.w[1];
    for (int k = 0; k < 300; ++k) step(m, s);
    const Vec3 expected = w0 * std::exp(-0.01 / i * 300 * world.dt);
    TUMBLE_MEASURED((s.w[1] - expected).norm() / expected.norm(), 1e-12);
    EXPECT_LT((s.w[1] - expected).norm() / expected.norm(), 1e-12);
    EXPECT_EQ(s.w[0], Vec3::Zero());
}

TEST(Damper, TumblingBodiesKeepTheirTotalMomentumAndOnlyLoseEnergy) {
    WorldDef world = free_world(1.0 / 120);
    world.dampers = {{0, 1, 0.02}};
    BodyDef a;
    a.shape = Shape::box(Vec3(0.1, 0.12, 0.5));
    a.mass = 2.0;
    a.angular_velocity = Vec3(0.1, 0.2, 6.0);
    BodyDef b = sphere(0.1, 4.0, Vec3(1, 0, 0), Vec3(0.3, -0.1, 5.0));
    const Model m = build_model(world, {a, b});
    State s = initial_state(m, {a, b});
    const Diagnostics d0 = diagnose(m, s);
    double last = d0.energy(), worst_l = 0;
    bool rose = false;
    for (int k = 0; k < 5000; ++k) {
        step(m, s);
        const Diagnostics d = diagnose(m, s);
        worst_l = std::max(worst_l, (d.angular_momentum - d0.angular_momentum).norm() /
                                        d0.angular_momentum.norm());
        // splitting's own energy error is bounded at O(h^2) and oscillates; the damper only takes
        // energy, so beyond that oscillation (1e-6 here) the energy never rises.
        rose |= d.energy() > last + 1e-6 * d0.energy();
        last = std::min(last, d.energy());
    }
    TUMBLE_MEASURED(worst_l, 1e-12);
    EXPECT_LT(worst_l, 1e-12);
    EXPECT_FALSE(rose);
    EXPECT_LT(last, 0.9 * d0.energy()); // and it does take energy
}

TEST(Damper, BuildRefusesADamperThatCannotBe) {
    const std::vector<BodyDef> bodies = {sphere(0.1, 1, Vec3::Zero(), Vec3::Zero()),
                                         sphere(0.1, 1, Vec3(1, 0, 0), Vec3::Zero())};
    for (const Damper& bad :
         {Damper{0, 0, 1.0}, Damper{0, 2, 1.0}, Damper{0, 1, -1.0}, Damper{0, 1, std::nan("")}}) {
        WorldDef world = free_world(0.01);
        world.dampers = {bad};
        EXPECT_THROW(build_model(world, bodies), ModelError);
    }
    // `exact` steps torque-free bodies only, and a damper is a torque.
    WorldDef world = free_world(0.01, Integrator::Exact);
    world.dampers = {{0, 1, 1.0}};
    try {
        build_model(world, bodies);
        ADD_FAILURE() << "exact took a damper";
    } catch (const ModelError& e) {
        EXPECT_EQ(e.field, "dampers");
        EXPECT_NE(std::string(e.what()).find("splitting_exact"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace tumble::physics
