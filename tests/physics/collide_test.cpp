// Narrow phase: every family of shape pairs gives the manifold geometry says it must (normal from
// A to B, separations, point counts), and ids stay put while the same features touch.
#include "physics/build.h"
#include "physics/collide.h"
#include "physics/gjk.h"
#include "support/measured.h"

#include <gtest/gtest.h>

namespace tumble::physics {
namespace {

ShapePose at(const Vec3& p, const Quat& q = Quat::Identity()) {
    return {p, q.toRotationMatrix()};
}

double deepest(const Manifold& m) {
    double d = 1e9;
    for (int k = 0; k < m.count; ++k) d = std::min(d, m.points[k].separation);
    return d;
}

TEST(Collide, SpheresAndPlanes) {
    Manifold m;
    collide_spheres(Vec3(0, 0, 0), 0.5, Vec3(0.9, 0, 0), 0.5, 0.0, m);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, -0.1, 1e-15);
    EXPECT_TRUE(m.normal.isApprox(Vec3::UnitX()));
    EXPECT_NEAR(m.points[0].point.x(), 0.45, 1e-15); // midway between the surfaces 0.4 and 0.5
    collide_spheres(Vec3(0, 0, 0), 0.5, Vec3(1.2, 0, 0), 0.5, 0.1, m);
    EXPECT_EQ(m.count, 0); // gap 0.2 > margin 0.1
    collide_plane_sphere(Vec3::UnitZ(), 0.0, Vec3(0, 0, 0.45), 0.5, 0.0, m);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, -0.05, 1e-15);
}

TEST(Collide, CapsulesLieOnTwoPoints) {
    Manifold m;
    // Lying on a plane: both ends.
    collide_plane_capsule(Vec3::UnitZ(), 0.0, Vec3(-0.3, 0, 0.1), Vec3(0.3, 0, 0.1), 0.1, 0.01, m);
    ASSERT_EQ(m.count, 2);
    EXPECT_NEAR(m.points[0].separation, 0.0, 1e-15);
    // Side by side: two points spanning the overlap of the cores.
    collide_capsules(Vec3(-0.3, 0, 0), Vec3(0.3, 0, 0), 0.1, Vec3(0.1, 0.19, 0), Vec3(0.7, 0.19, 0),
                     0.1, 0.01, m);
    ASSERT_EQ(m.count, 2);
    EXPECT_TRUE(m.normal.isApprox(Vec3::UnitY()));
    EXPECT_NEAR(m.points[0].separation, -0.01, 1e-12);
    EXPECT_NEAR(std::abs(m.points[0].point.x() - m.points[1].point.x()), 0.2, 1e-12);
    // Crossed: one point.
    collide_capsules(Vec3(-0.3, 0, 0), Vec3(0.3, 0, 0), 0.1, Vec3(0, -0.3, 0.15),
                     Vec3(0, 0.3, 0.15), 0.1, 0.01, m);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, -0.05, 1e-12);
    EXPECT_TRUE(m.normal.isApprox(Vec3::UnitZ()));
}

TEST(Collide, BoxOnPlaneAndBoxOnBoxGiveFourPoints) {
    const ConvexHull box = make_box_hull(Vec3(0.5, 0.5, 0.5));
    Manifold m;
    collide_plane_hull(Vec3::UnitZ(), 0.0, box, at(Vec3(0, 0, 0.49)), 0.005, m);
    ASSERT_EQ(m.count, 4);
    EXPECT_NEAR(deepest(m), -0.01, 1e-12);
    // A box resting on a box, offset and turned about z: face contact, clipped to 4 points.
    collide_hulls(box, at(Vec3(0, 0, 0)), box,
                  at(Vec3(0.3, 0.1, 0.999), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()))), 0.005, m);
    ASSERT_EQ(m.count, 4);
    EXPECT_TRUE(m.normal.isApprox(Vec3::UnitZ(), 1e-12));
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(m.points[k].separation, -0.001, 1e-12);
}

TEST(Collide, BoxEdgeAcrossBoxEdge) {
    // Two boxes turned 45 degrees about crossing axes meet edge to edge: one point, normal along
    // the edges' common perpendicular.
    const ConvexHull box = make_box_hull(Vec3(0.5, 0.5, 0.5));
    const Quat qa(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()));
    const Quat qb(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()));
    const double reach = 2 * 0.5 * std::sqrt(2.0);
    Manifold m;
    collide_hulls(box, at(Vec3::Zero(), qa), box, at(Vec3(0, 0, reach - 0.01), qb), 0.005, m);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, -0.01, 1e-9);
    EXPECT_TRUE(m.normal.isApprox(Vec3::UnitZ(), 1e-9));
}

TEST(Collide, SphereAgainstBoxFaceEdgeCornerAndInside) {
    Model model;
    const ConvexHull box = make_box_hull(Vec3(0.5, 0.5, 0.5));
    Manifold m;
    collide_hull_sphere(box, at(Vec3::Zero()), Vec3(0, 0, 0.7), 0.25, 0.0, m); // face
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, -0.05, 1e-12);
    collide_hull_sphere(box, at(Vec3::Zero()), Vec3(0.6, 0, 0.6), 0.25, 0.0, m); // edge
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, 0.1 * std::sqrt(2.0) - 0.25, 1e-12);
    EXPECT_TRUE(m.normal.isApprox(Vec3(1, 0, 1).normalized(), 1e-12));
    collide_hull_sphere(box, at(Vec3::Zero()), Vec3(0.6, 0.6, 0.6), 0.25, 0.0, m); // corner
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, 0.1 * std::sqrt(3.0) - 0.25, 1e-12);
    collide_hull_sphere(box, at(Vec3::Zero()), Vec3(0.1, 0, 0.4), 0.25, 0.0, m); // inside
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, -0.1 - 0.25, 1e-12);
    EXPECT_TRUE(m.normal.isApprox(Vec3::UnitZ()));
}

TEST(Collide, CapsuleFlatOnBoxAndThroughBox) {
    const ConvexHull box = make_box_hull(Vec3(1, 1, 0.5));
    Manifold m;
    collide_hull_capsule(box, at(Vec3::Zero()), Vec3(-0.4, 0, 0.59), Vec3(0.4, 0, 0.59), 0.1, 0.005,
                         m);
    ASSERT_EQ(m.count, 2);
    EXPECT_NEAR(m.points[0].separation, -0.01, 1e-12);
    EXPECT_NEAR(m.points[1].separation, -0.01, 1e-12);
    // Core inside the box near its top: separating axis is the top face.
    collide_hull_capsule(box, at(Vec3::Zero()), Vec3(-0.4, 0, 0.45), Vec3(0.4, 0, 0.45), 0.1, 0.005,
                         m);
    ASSERT_EQ(m.count, 2);
    EXPECT_NEAR(m.points[0].separation, -0.15, 1e-12);
    EXPECT_TRUE(m.normal.isApprox(Vec3::UnitZ()));
}

TEST(Collide, GjkDistanceOfSegmentToBox) {
    const ConvexHull box = make_box_hull(Vec3(1, 1, 1));
    const Vec3 seg[2] = {Vec3(2, 2, 0), Vec3(3, 1, 0)};
    const GjkResult g = gjk_distance(seg, box.vertices);
    ASSERT_FALSE(g.overlap);
    // Closest: the segment's point (2, 2, 0) to the box edge x = y = 1: distance sqrt(2).
    const double err = std::abs(g.distance - std::sqrt(2.0));
    TUMBLE_MEASURED(err, 1e-12);
    EXPECT_LT(err, 1e-12);
    const Vec3 inside[1] = {Vec3(0.2, 0.1, 0)};
    EXPECT_TRUE(gjk_distance(inside, box.vertices).overlap);
}

TEST(Collide, DispatchFlipsTheNormalForEitherOrder) {
    BodyDef ball, crate;
    ball.shape = Shape::sphere(0.25);
    crate.shape = Shape::box(Vec3(0.5, 0.5, 0.5));
    const Model model = build_model({}, {ball, crate});
    Manifold ab, ba;
    collide(model, 0, at(Vec3(0, 0, 0.7)), 1, at(Vec3::Zero()), 0.0, ab);
    collide(model, 1, at(Vec3::Zero()), 0, at(Vec3(0, 0, 0.7)), 0.0, ba);
    ASSERT_EQ(ab.count, 1);
    ASSERT_EQ(ba.count, 1);
    EXPECT_TRUE(ab.normal.isApprox(-Vec3::UnitZ())); // from the ball (A) down to the box
    EXPECT_TRUE(ba.normal.isApprox(Vec3::UnitZ()));
    EXPECT_DOUBLE_EQ(ab.points[0].separation, ba.points[0].separation);
}

TEST(Collide, FeatureIdsSurviveSmallMotion) {
    // Warm starting matches points by id: a resting box nudged and turned a little keeps its ids
    // (two corners over the lower box's face, two where its edges cross the face's border).
    const ConvexHull box = make_box_hull(Vec3(0.5, 0.5, 0.5));
    const ConvexHull top = make_box_hull(Vec3(0.5, 0.3, 0.5));
    Manifold a, b;
    collide_hulls(box, at(Vec3::Zero()), top, at(Vec3(0.1, 0, 0.999)), 0.005, a);
    collide_hulls(box, at(Vec3::Zero()), top,
                  at(Vec3(0.1003, 0.0002, 0.9991),
                     Quat(Eigen::AngleAxisd(0.002, Vec3(1, 1, 1).normalized()))),
                  0.005, b);
    ASSERT_EQ(a.count, 4);
    ASSERT_EQ(b.count, 4);
    int matched = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) matched += a.points[i].id == b.points[j].id;
    EXPECT_EQ(matched, 4);
}

} // namespace
} // namespace tumble::physics
