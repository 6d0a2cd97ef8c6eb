// The contact stage works with every named integrator: the test scenes run without exploding and
// keep their physics (a ball bounces to its apex, a box sticks on a ramp, a tower stands); and a
// contact scene whose bodies never touch steps exactly as the integrator alone would.
#include "physics/scenes/contact_scenes.h"
#include "scene_sim.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace tumble::physics {
namespace {

using test::Sim;

TEST(ContactIntegrators, EveryIntegratorBouncesHoldsAndStacks) {
    for (const IntegratorInfo& info : integrators()) {
        SCOPED_TRACE(std::string(info.name));
        scenes::Scene ball = scenes::ball_drop(0.8, 1.0, 1.0 / 240.0);
        ball.world.integrator = info.id;
        Sim b(ball);
        double apex = 0.0;
        bool bounced = false;
        for (int k = 0; k < b.steps_for(1.4); ++k) {
            const double before = b.state.v[1].z();
            b.steps(1);
            bounced |= before < 0.0 && b.state.v[1].z() > 0.0;
            if (bounced) apex = std::max(apex, b.state.x[1].z() - 0.1);
        }
        const double apex_error = std::abs(apex / 0.64 - 1.0);

        scenes::Scene ramp =
            scenes::incline(20.0 * std::numbers::pi / 180.0, 0.5, 1.0 / 240.0, false);
        ramp.world.integrator = info.id;
        Sim r(ramp);
        const Vec3 start = r.state.x[1];
        r.steps(r.steps_for(3.0));
        const double creep = (r.state.x[1] - start).norm();

        scenes::Scene stack = scenes::box_stack(5, 0.5, 1.0 / 240.0);
        stack.world.integrator = info.id;
        Sim t(stack);
        const Vec3 top = t.state.x[5];
        t.steps(t.steps_for(3.0));
        const double drift = (t.state.x[5] - top).norm();

        std::printf("%-20s apex error %.4f, creep %.2e m, tower top drift %.2e m\n",
                    std::string(info.name).c_str(), apex_error, creep, drift);
        EXPECT_LT(apex_error, 0.03);
        EXPECT_LT(creep, 1e-3);
        EXPECT_LT(drift, 0.01);
    }
}

TEST(ContactIntegrators, BodiesThatNeverTouchStepAsWithoutContacts) {
    // Two tumbling bodies far apart, flying apart under the same gravity: they cannot touch
    // (can_touch.h), so the scene has no contact stage. Forced on, the stage finds nothing and
    // hands the whole step to the integrator: the states are bit-identical to stepping each body
    // alone.
    for (const IntegratorInfo& info : integrators()) {
        BodyDef book;
        book.shape = Shape::box(Vec3(0.1, 0.03, 0.15));
        book.mass = 0.6;
        book.angular_velocity = Vec3(0.02, 6.0, 0.02);
        BodyDef ball;
        ball.position = Vec3(10.0, 0.0, 0.0);
        ball.velocity = Vec3(0.5, 0.0, 4.0);
        WorldDef w;
        w.integrator = info.id;
        Model both = build_model(w, {book, ball});
        const Model alone = build_model(w, {book});
        ASSERT_FALSE(both.passes.contacts) << both.touch.why;
        ASSERT_FALSE(alone.passes.contacts);
        both.passes.contacts = true;
        State s2 = initial_state(both, {book, ball}), s1 = initial_state(alone, {book});
        for (int k = 0; k < 500; ++k) step(both, s2), step(alone, s1);
        EXPECT_EQ(0,
                  std::memcmp(s2.q[0].coeffs().data(), s1.q[0].coeffs().data(), 4 * sizeof(double)))
            << info.name;
        EXPECT_EQ(s2.w[0], s1.w[0]) << info.name;
    }
}

} // namespace
} // namespace tumble::physics
