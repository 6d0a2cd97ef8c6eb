// The shadow test's own geometry (light_rays.h) against answers worked out by hand: where a ray
// enters a sphere, a box, a capsule and a triangle mesh, and that it misses them when it should.
#include "light_rays.h"

#include <gtest/gtest.h>

namespace tumble::render::test {
namespace {

BodyShape at(const physics::Shape& s, glm::dvec3 position, const MeshData* mesh = nullptr) {
    physics::Pose pose{physics::Vec3(position.x, position.y, position.z),
                       physics::Quat::Identity()};
    return body_shape(s, pose, mesh);
}

const glm::dvec3 kUp(0.0, 0.0, 1.0);

TEST(LightRays, EntryIntoSphereBoxAndCapsule) {
    const BodyShape ball = at(physics::Shape::sphere(0.5), {0.0, 0.0, 2.0});
    EXPECT_NEAR(ray_entry(ball, {0.0, 0.0, 0.0}, kUp), 1.5, 1e-12);
    EXPECT_NEAR(ray_entry(ball, {0.3, 0.0, 0.0}, kUp), 2.0 - 0.4, 1e-12); // 0.3-0.4-0.5 triangle
    EXPECT_EQ(ray_entry(ball, {0.6, 0.0, 0.0}, kUp), kMiss);
    EXPECT_EQ(ray_entry(ball, {0.0, 0.0, 3.0}, kUp), kMiss); // it lies behind the origin

    const BodyShape box = at(physics::Shape::box({0.5, 0.2, 0.1}), {0.0, 0.0, 1.0});
    EXPECT_NEAR(ray_entry(box, {0.4, 0.1, 0.0}, kUp), 0.9, 1e-12);
    EXPECT_EQ(ray_entry(box, {0.4, 0.3, 0.0}, kUp), kMiss);
    const glm::dvec3 slant = glm::normalize(glm::dvec3(1.0, 0.0, 1.0));
    EXPECT_NEAR(ray_entry(box, {-0.5, 0.0, 0.0}, slant), 0.9 * std::sqrt(2.0), 1e-12);

    // Capsule along z from -0.5 to 0.5, radius 0.25: from the side it enters the cylinder, from
    // below the end cap.
    const BodyShape capsule = at(physics::Shape::capsule(0.25, 0.5), {0.0, 0.0, 0.0});
    EXPECT_NEAR(ray_entry(capsule, {-2.0, 0.0, 0.2}, {1.0, 0.0, 0.0}), 1.75, 1e-9);
    EXPECT_NEAR(ray_entry(capsule, {0.0, 0.0, -2.0}, kUp), 2.0 - 0.75, 1e-9);
    EXPECT_EQ(ray_entry(capsule, {-2.0, 0.3, 0.0}, {1.0, 0.0, 0.0}), kMiss);
    EXPECT_EQ(ray_entry(capsule, {0.0, 0.0, 0.0}, kUp), 0.0); // from inside
}

TEST(LightRays, EntryIntoATriangleMesh) {
    // A tetrahedron with its base triangle at z = 1.
    MeshData m;
    for (glm::vec3 p :
         {glm::vec3(-1, -1, 1), glm::vec3(1, -1, 1), glm::vec3(0, 1, 1), glm::vec3(0, 0, 2)})
        m.vertices.push_back({p, {0, 0, 1}});
    m.indices = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
    const BodyShape tet = at(physics::Shape::mesh(), {0.0, 0.0, 0.0}, &m);
    EXPECT_NEAR(ray_entry(tet, {0.0, 0.0, 0.0}, kUp), 1.0, 1e-12);
    EXPECT_EQ(ray_entry(tet, {0.0, -1.5, 0.0}, kUp), kMiss);
    EXPECT_TRUE(blocks(tet, {0.2, 0.0, -3.0}, kUp));
}

} // namespace
} // namespace tumble::render::test
