// build_model() refuses what no rigid body can be, naming the body and the field.
#include "physics/build.h"
#include "physics/step.h"

#include <gtest/gtest.h>

#include <limits>

namespace tumble::physics {
namespace {

ModelError build_error(const WorldDef& w, const std::vector<BodyDef>& bodies) {
    try {
        Model m = build_model(w, bodies);
        (void)initial_state(m, bodies);
    } catch (const ModelError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a ModelError";
    return ModelError(-2, "", "");
}

TEST(BuildValidation, RefusesNonPositiveMass) {
    BodyDef ok, bad;
    bad.mass = 0.0;
    const ModelError e = build_error({}, {ok, bad});
    EXPECT_EQ(e.body, 1);
    EXPECT_EQ(e.field, "mass");
}

TEST(BuildValidation, RefusesInertiaViolatingTriangleInequality) {
    BodyDef b;
    b.inertia = Mat3(Vec3(1.0, 1.0, 3.0).asDiagonal()); // 1 + 1 < 3
    const ModelError e = build_error({}, {b});
    EXPECT_EQ(e.field, "inertia");
    EXPECT_NE(std::string(e.what()).find("triangle inequality"), std::string::npos) << e.what();
}

TEST(BuildValidation, AcceptsFlatPlateOnTheTriangleBoundary) {
    BodyDef b;
    b.inertia = Mat3(Vec3(1.0, 2.0, 3.0).asDiagonal()); // I3 = I1 + I2: a thin plate
    EXPECT_NO_THROW(build_model({}, {b}));
}

TEST(BuildValidation, RefusesNonPositiveInertiaAndNonFiniteValues) {
    BodyDef b;
    b.inertia = Mat3(Vec3(1.0, 0.0, 1.0).asDiagonal());
    EXPECT_EQ(build_error({}, {b}).field, "inertia");
    BodyDef c;
    c.position.x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(build_error({}, {c}).field, "position");
    WorldDef w;
    w.dt = 0.0;
    EXPECT_EQ(build_error(w, {}).field, "dt");
    EXPECT_EQ(build_error(w, {}).body, -1);
}

TEST(BuildValidation, RefusesMovingPlaneAndZeroSizeShapes) {
    BodyDef plane;
    plane.shape = Shape::plane();
    EXPECT_EQ(build_error({}, {plane}).field, "static");
    BodyDef box;
    box.shape = Shape::box(Vec3(0.1, 0.0, 0.1));
    EXPECT_EQ(build_error({}, {box}).field, "size");
    BodyDef ball;
    ball.shape = Shape::sphere(-1.0);
    EXPECT_EQ(build_error({}, {ball}).field, "radius");
}

TEST(BuildValidation, NonDiagonalInertiaIsDiagonalised) {
    // A box's inertia expressed in axes rotated by 30 degrees about z must give back the box's
    // principal moments, and the body frame must still move as the user wrote it.
    const Vec3 moments(1.0, 2.0, 2.5);
    const Mat3 r = Eigen::AngleAxisd(0.5235987755982988, Vec3::UnitZ()).toRotationMatrix();
    BodyDef b;
    b.inertia = r * moments.asDiagonal() * r.transpose();
    b.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
    const Model m = build_model({}, {b});
    Vec3 got = m.inertia[0];
    std::sort(got.data(), got.data() + 3);
    EXPECT_LT((got - moments).norm(), 1e-12);
    const State s = initial_state(m, {b});
    EXPECT_LT(rotation_angle_between(body_pose(m, s, 0).orientation, b.orientation), 1e-12);
}

TEST(Divergence, StopsNamingBodyAndStep) {
    // rk4 far beyond its stability limit (h |w| = 50) on a tumbling box overflows within a few
    // dozen steps; the run must stop with body 1 named, not continue with NaN. The box sits 100 m
    // from the calm sphere and neither travels, so they cannot touch (its spin sweeps a speculative
    // margin of h |w| swing = 37 m per step) and no contact is involved.
    WorldDef w;
    w.gravity = Vec3::Zero();
    w.dt = 0.5;
    BodyDef calm, wild;
    wild.shape = Shape::box(Vec3(0.1, 0.2, 0.3));
    wild.position = Vec3(100.0, 0.0, 0.0);
    wild.angular_velocity = Vec3(0.1, 100.0, 0.1);
    Model m = build_model(w, {calm, wild});
    ASSERT_FALSE(m.passes.contacts) << m.touch.why;
    State s = initial_state(m, {calm, wild});
    try {
        for (int k = 0; k < 100000; ++k) step(m, s);
        FAIL() << "expected divergence";
    } catch (const DivergenceError& e) {
        EXPECT_EQ(e.body, 1);
        EXPECT_GT(e.step, 0);
        EXPECT_NE(std::string(e.what()).find("body 1"), std::string::npos);
    }
}

} // namespace
} // namespace tumble::physics
