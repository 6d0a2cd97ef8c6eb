// The decision that turns the contact stage on (physics/can_touch.h): exact for free relative
// flight, conservative under relative acceleration, and never "cannot touch" for bodies that meet.
#include "physics/build.h"
#include "physics/step.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::physics {
namespace {

BodyDef ball_at(const Vec3& x, const Vec3& v = Vec3::Zero()) {
    BodyDef b;
    b.shape = Shape::sphere(0.1);
    b.position = x;
    b.velocity = v;
    return b;
}

WorldDef no_gravity() {
    WorldDef w;
    w.gravity = Vec3::Zero();
    return w;
}

TEST(CanTouch, ALoneBodyOrOnlyStaticBodiesNever) {
    EXPECT_FALSE(build_model({}, {ball_at(Vec3::Zero())}).passes.contacts);
    BodyDef floor;
    floor.shape = Shape::plane();
    floor.motion = Motion::Static;
    BodyDef wall;
    wall.shape = Shape::box(Vec3(0.1, 1, 1));
    wall.motion = Motion::Static;
    wall.position = Vec3(0, 0, 2);
    const Model m = build_model({}, {floor, wall});
    EXPECT_FALSE(m.passes.contacts) << m.touch.why;
}

TEST(CanTouch, ClosestApproachInFreeFlightDecides) {
    // Two balls of radius 0.1 on parallel tracks 1 m apart in x, passing with a lateral offset.
    // The margin is 2 x 2 mm (the speculative distance) + dt |u| = 0.004 + 2/240 = 0.0123 m, so
    // they can touch when the offset is under 0.2123 m, at t = 0.5 s when they pass.
    for (const double offset : {0.20, 0.25, 0.5}) {
        const Model m = build_model(no_gravity(), {ball_at(Vec3(0, 0, 0), Vec3(1, 0, 0)),
                                                   ball_at(Vec3(1, offset, 0), Vec3(-1, 0, 0))});
        const bool expected = offset < 0.2123;
        EXPECT_EQ(m.passes.contacts, expected) << offset << ": " << m.touch.why;
        if (m.passes.contacts) {
            TUMBLE_MEASURED(std::abs(m.touch.when - 0.5), 1e-12);
            EXPECT_NEAR(m.touch.when, 0.5, 1e-12);
            EXPECT_EQ(m.touch.a, 0);
            EXPECT_EQ(m.touch.b, 1);
        } else {
            const double clearance = offset - 0.2 - (0.004 + 2.0 / 240.0);
            TUMBLE_MEASURED(std::abs(m.touch.min_clearance - clearance), 1e-12);
            EXPECT_NEAR(m.touch.min_clearance, clearance, 1e-12);
        }
    }
}

TEST(CanTouch, RelativeAccelerationCountsAsTouching) {
    // The same gravity on both: relative flight is free, and two balls moving apart never meet.
    const Model apart = build_model(
        {}, {ball_at(Vec3(0, 0, 5), Vec3(0, 0, 1)), ball_at(Vec3(1, 0, 5), Vec3(1, 0, 0))});
    EXPECT_FALSE(apart.passes.contacts) << apart.touch.why;
    // Different gravity scales: they accelerate relative to each other (conservative answer).
    BodyDef floating = ball_at(Vec3(1, 0, 5), Vec3(1, 0, 0));
    floating.gravity_scale = 0.0;
    const Model m = build_model({}, {ball_at(Vec3(0, 0, 5), Vec3(0, 0, 1)), floating});
    EXPECT_TRUE(m.passes.contacts);
    EXPECT_NE(m.touch.why.find("accelerate"), std::string::npos) << m.touch.why;
}

TEST(CanTouch, PlanesByTheSignedDistance) {
    BodyDef floor;
    floor.shape = Shape::plane();
    floor.motion = Motion::Static;
    // Above the floor without gravity: moving up never touches, moving down always does.
    EXPECT_FALSE(build_model(no_gravity(), {floor, ball_at(Vec3(0, 0, 1), Vec3(3, 0, 0.1))})
                     .passes.contacts);
    EXPECT_TRUE(build_model(no_gravity(), {floor, ball_at(Vec3(0, 0, 1), Vec3(0, 0, -1e-3))})
                    .passes.contacts);
    // Resting on it: within reach from the start.
    EXPECT_TRUE(build_model(no_gravity(), {floor, ball_at(Vec3(0, 0, 0.1))}).passes.contacts);
    // Gravity pulls the ball down on the floor.
    const Model fall = build_model({}, {floor, ball_at(Vec3(0, 0, 1), Vec3(0, 0, 10))});
    EXPECT_TRUE(fall.passes.contacts);
    EXPECT_EQ(fall.touch.a, 0);
    EXPECT_EQ(fall.touch.b, 1);
}

TEST(CanTouch, ASceneDecidedApartHasNoContactPointWhenForced) {
    // Two balls passing just outside the margin, contact stage forced on: no manifold, ever.
    const std::vector<BodyDef> bodies = {ball_at(Vec3(0, 0, 0), Vec3(1, 0, 0)),
                                         ball_at(Vec3(1, 0.23, 0), Vec3(-1, 0, 0))};
    Model m = build_model(no_gravity(), bodies);
    ASSERT_FALSE(m.passes.contacts) << m.touch.why;
    m.passes.contacts = true;
    State s = initial_state(m, bodies);
    StepWorkspace ws(1);
    int manifolds = 0;
    for (int k = 0; k < 240; ++k) {
        step(m, s, ws);
        manifolds += ws.contacts.stats().manifolds;
    }
    TUMBLE_MEASURED(manifolds, 0);
    EXPECT_EQ(manifolds, 0);
}

} // namespace
} // namespace tumble::physics
