// Exact solutions of the foundation's integrator: free fall and projectile motion (translation
// is exact for constant force), torque-free spin, and the conserved quantities of tumbling.
#include "physics/build.h"
#include "physics/diagnostics.h"
#include "physics/step.h"

#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::physics {
namespace {

struct World {
    Model model;
    State state;
};

World make_world(const WorldDef& w, const std::vector<BodyDef>& bodies) {
    World out{build_model(w, bodies), {}};
    out.state = initial_state(out.model, bodies);
    return out;
}

void run(World& w, int steps) {
    for (int k = 0; k < steps; ++k) step(w.model, w.state);
}

double rel(const Vec3& a, const Vec3& b) {
    return (a - b).norm() / b.norm();
}

TEST(FreeMotion, ProjectileMatchesExactParabola) {
    // x(t) = x0 + v0 t + 1/2 g t^2 and v(t) = v0 + g t, at t = 2 s after 480 steps of 1/240 s.
    WorldDef wd;
    wd.gravity = Vec3(0.0, 0.0, -9.81);
    wd.dt = 1.0 / 240.0;
    BodyDef ball;
    ball.position = Vec3(1.0, -2.0, 3.0);
    ball.velocity = Vec3(2.0, 1.0, 12.0);
    World w = make_world(wd, {ball});
    run(w, 480);
    const double t = w.state.time(w.model);
    EXPECT_EQ(t, 2.0);
    const Vec3 x_exact = ball.position + ball.velocity * t + 0.5 * wd.gravity * t * t;
    const Vec3 v_exact = ball.velocity + wd.gravity * t;
    const double err_x = rel(w.state.x[0], x_exact), err_v = rel(w.state.v[0], v_exact);
    TUMBLE_MEASURED(err_x, 1e-12);
    TUMBLE_MEASURED(err_v, 1e-12);
    EXPECT_LT(err_x, 1e-12);
    EXPECT_LT(err_v, 1e-12);
}

TEST(FreeMotion, FreeFallFromRest) {
    WorldDef wd;
    wd.dt = 0.01;
    BodyDef ball;
    ball.position = Vec3(0.0, 0.0, 100.0);
    World w = make_world(wd, {ball});
    run(w, 300);
    const double t = 3.0;
    EXPECT_NEAR(w.state.x[0].z(), 100.0 - 0.5 * 9.81 * t * t, 1e-12 * 100.0);
    EXPECT_NEAR(w.state.v[0].z(), -9.81 * t, 1e-12 * 9.81 * t);
}

TEST(FreeMotion, TorqueFreeSphereKeepsItsAngularVelocity) {
    WorldDef wd;
    wd.gravity = Vec3::Zero();
    BodyDef sphere;
    sphere.shape = Shape::sphere(0.3);
    sphere.angular_velocity = Vec3(3.0, -7.0, 11.0);
    World w = make_world(wd, {sphere});
    EXPECT_FALSE(w.model.passes.gyroscopic); // isotropic: no gyroscopic work at all
    run(w, 2400);
    EXPECT_EQ(w.state.w[0], sphere.angular_velocity); // bit-exact: dw/dt = 0 is added as zeros
    EXPECT_NEAR(w.state.q[0].norm(), 1.0, 1e-15);
}

TEST(FreeMotion, TumblingBoxConservesWorldAngularMomentumAndEnergy) {
    // MuJoCo's test box: half sizes (0.1, 0.2, 0.3), 1 kg, w0 = (1, 2, 3) rad/s, no gravity.
    WorldDef wd;
    wd.gravity = Vec3::Zero();
    wd.dt = 0.01;
    BodyDef box;
    box.shape = Shape::box(Vec3(0.1, 0.2, 0.3));
    box.angular_velocity = Vec3(1.0, 2.0, 3.0);
    World w = make_world(wd, {box});
    const Diagnostics d0 = diagnose(w.model, w.state);
    double worst_l = 0.0, worst_e = 0.0;
    for (int k = 0; k < 500; ++k) { // 5 s
        step(w.model, w.state);
        const Diagnostics d = diagnose(w.model, w.state);
        worst_l = std::max(worst_l, rel(d.angular_momentum, d0.angular_momentum));
        worst_e = std::max(worst_e, std::abs(d.energy() / d0.energy() - 1.0));
    }
    TUMBLE_MEASURED(worst_l, 1e-7);
    TUMBLE_MEASURED(worst_e, 1e-7);
    EXPECT_LT(worst_l, 1e-7);
    EXPECT_LT(worst_e, 1e-7);
}

} // namespace
} // namespace tumble::physics
