// Sleeping: a settled stack sleeps (no motion at all, no solver work), a ball landing on it wakes
// the whole island, and the scene switch turns sleeping off.
#include "physics/scenes/contact_scenes.h"
#include "scene_sim.h"
#include "support/measured.h"

#include <gtest/gtest.h>

namespace tumble::physics {
namespace {

scenes::Scene stack_and_ball(bool sleeping, double ball_height) {
    scenes::Scene s = scenes::box_stack(3, 0.5, 1.0 / 240.0);
    s.world.contact.sleeping = sleeping;
    BodyDef ball;
    ball.shape = Shape::sphere(0.1);
    ball.mass = 2.0;
    ball.position = Vec3(0.1, 0.0, ball_height);
    s.bodies.push_back(ball);
    return s;
}

TEST(Sleep, SettledStackSleepsAndIsWokenByAFallingBall) {
    // The ball starts 30 m up: it lands about 2.4 s in, after the stack has fallen asleep.
    test::Sim run(stack_and_ball(true, 31.0));
    StepWorkspace ws;
    for (int k = 0; k < 480; ++k) step(run.model, run.state, ws);
    for (int i = 1; i <= 3; ++i) EXPECT_TRUE(run.state.sleep.asleep[i]) << "box " << i;
    EXPECT_FALSE(run.state.sleep.asleep[4]); // the ball is still falling
    const State asleep = run.state;
    for (int k = 0; k < 60; ++k) step(run.model, run.state, ws);
    for (int i = 1; i <= 3; ++i) EXPECT_EQ(run.state.x[i], asleep.x[i]); // not even round-off
    // The ball hits the top box: the island (all three boxes) wakes and takes the blow.
    bool woke = false;
    for (int k = 0; k < 240 && !woke; ++k) {
        step(run.model, run.state, ws);
        woke = !run.state.sleep.asleep[1] && !run.state.sleep.asleep[3];
    }
    EXPECT_TRUE(woke);
    const double moved = (run.state.x[3] - asleep.x[3]).norm();
    TUMBLE_MEASURED(moved, 1e-6);
    EXPECT_GT(moved, 1e-6);
}

TEST(Sleep, SwitchedOffNothingSleeps) {
    test::Sim run(stack_and_ball(false, 31.0));
    run.steps(480);
    for (int i = 1; i <= 4; ++i) EXPECT_FALSE(run.state.sleep.asleep[i]);
}

} // namespace
} // namespace tumble::physics
