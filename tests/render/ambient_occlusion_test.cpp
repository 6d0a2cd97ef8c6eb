// The geometry of ambient occlusion (render/ambient_occlusion.h), without GL: each shape's
// stand-in ellipsoid is the uniform ellipsoid with the shape's inertia, each body finds the
// occluders that reach it, and the ground gets a decal under every body near it.
#include "render/ambient_occlusion.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace tumble::render {
namespace {

// Semi-axes of the uniform ellipsoid with principal moments I (per unit mass): an ellipsoid
// with semi-axes a, b, c has I_x = (b^2 + c^2) / 5 and so on, so a^2 = 5/2 (I_y + I_z - I_x).
glm::vec3 equivalent_semi_axes(glm::vec3 I) {
    return {std::sqrt(2.5f * (I.y + I.z - I.x)), std::sqrt(2.5f * (I.z + I.x - I.y)),
            std::sqrt(2.5f * (I.x + I.y - I.z))};
}

// |A (p - c)|: 1 on the occluder's surface.
float unit_distance(const Occluder& o, glm::vec3 p) {
    return glm::length(o.to_unit * (p - o.centre));
}

TEST(AmbientOcclusion, ABoxStandsInAsTheEllipsoidWithItsInertia) {
    const glm::vec3 h(0.5f, 0.2f, 0.1f); // half extents
    // Box inertia per unit mass: I_x = (h_y^2 + h_z^2) / 3, ...
    const glm::vec3 I((h.y * h.y + h.z * h.z) / 3.0f, (h.z * h.z + h.x * h.x) / 3.0f,
                      (h.x * h.x + h.y * h.y) / 3.0f);
    const glm::vec3 semi = equivalent_semi_axes(I);
    const glm::mat4 pose = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), 0.7f,
                                       glm::normalize(glm::vec3(1, 1, 0)));
    const Occluder o = occluder_of(MeshKind::Box, glm::scale(pose, h), {});
    for (int k = 0; k < 3; ++k) {
        glm::vec3 axis(0.0f);
        axis[k] = semi[k];
        const glm::vec3 tip = glm::vec3(pose * glm::vec4(axis, 1.0f));
        EXPECT_NEAR(unit_distance(o, tip), 1.0f, 1e-5f) << "axis " << k;
    }
    EXPECT_NEAR(o.bound, semi.x, 1e-5f);
}

TEST(AmbientOcclusion, ACylinderAndASphereStandInAsTheirEquivalentEllipsoids) {
    const float r = 0.3f, l = 0.8f; // radius and half length
    // Solid cylinder per unit mass: I_z = r^2 / 2, I_x = I_y = r^2 / 4 + l^2 / 3.
    const glm::vec3 I(r * r / 4 + l * l / 3, r * r / 4 + l * l / 3, r * r / 2);
    const glm::vec3 semi = equivalent_semi_axes(I);
    const Occluder c =
        occluder_of(MeshKind::Cylinder, glm::scale(glm::mat4(1.0f), glm::vec3(r, r, l)), {});
    EXPECT_NEAR(unit_distance(c, {semi.x, 0, 0}), 1.0f, 1e-5f);
    EXPECT_NEAR(unit_distance(c, {0, 0, semi.z}), 1.0f, 1e-5f);
    // A sphere is its own equivalent ellipsoid (I = 2 r^2 / 5 on every axis).
    const Occluder s = occluder_of(
        MeshKind::Sphere,
        glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 2)), glm::vec3(0.25f)), {});
    EXPECT_NEAR(equivalent_semi_axes(glm::vec3(0.4f * 0.0625f)).x, 0.25f, 1e-6f);
    EXPECT_NEAR(unit_distance(s, {0.25f, 0, 2}), 1.0f, 1e-6f);
}

Occluder sphere_at(glm::vec3 c, float r, int body) {
    Occluder o = occluder_of(MeshKind::Sphere,
                             glm::scale(glm::translate(glm::mat4(1.0f), c), glm::vec3(r)), {});
    o.body = body;
    return o;
}

TEST(AmbientOcclusion, EachBodyGetsTheTwoOccludersThatReachItMostAndNeverItself) {
    // A row of unit spheres 2.5 apart (reach 3 radii) and a far one; a capsule-like body made
    // of two shapes (body 9) sits between 0 and 1.
    std::vector<Occluder> occ = {sphere_at({0, 0, 0}, 1, 0),    sphere_at({2.5f, 0, 0}, 1, 1),
                                 sphere_at({5.0f, 0, 0}, 1, 2), sphere_at({100, 0, 0}, 1, 3),
                                 sphere_at({1.2f, 3, 0}, 1, 9), sphere_at({1.3f, 3, 0}, 1, 9)};
    std::vector<Receiver> rec;
    for (const Occluder& o : occ) rec.push_back({o.centre, 1.0f, o.body});
    std::vector<std::array<std::int32_t, 2>> near;
    std::vector<std::int32_t> scratch;
    nearest_occluders(occ, rec, near, scratch);
    ASSERT_EQ(near.size(), occ.size());
    EXPECT_EQ(near[1][0], 0); // ties go to the lower index
    EXPECT_EQ(near[1][1], 2);
    EXPECT_EQ(near[3][0], -1); // nothing reaches the far sphere
    EXPECT_EQ(near[3][1], -1);
    for (std::size_t i = 4; i < 6; ++i) { // the two-shape body never darkens itself
        for (std::int32_t k : near[i]) {
            if (k >= 0) {
                EXPECT_NE(occ[std::size_t(k)].body, 9);
            }
        }
    }
    // Brute force agrees: the nearest by depth in reach, for every receiver.
    for (std::size_t r = 0; r < rec.size(); ++r) {
        float best = 1e30f;
        std::int32_t pick = -1;
        for (std::size_t o = 0; o < occ.size(); ++o) {
            if (occ[o].body == rec[r].body) continue;
            const float gap = glm::length(rec[r].centre - occ[o].centre) - rec[r].bound -
                              kOcclusionReach * occ[o].bound;
            if (gap < 0 && gap / (kOcclusionReach * occ[o].bound) < best) {
                best = gap / (kOcclusionReach * occ[o].bound);
                pick = std::int32_t(o);
            }
        }
        EXPECT_EQ(near[r][0], pick) << "receiver " << r;
    }
}

TEST(AmbientOcclusion, TheGroundGetsADecalUnderEveryBodyWithinReachAndNoOther) {
    const glm::mat4 ground = glm::scale(glm::mat4(1.0f), glm::vec3(5.0f, 5.0f, 1.0f));
    const std::vector<Occluder> occ = {
        sphere_at({1, 1, 0.5f}, 0.5f, 0),  // resting: a decal
        sphere_at({0, 0, 1.4f}, 0.5f, 1),  // 1.4 above, reach 1.5: a small decal
        sphere_at({0, 0, 1.6f}, 0.5f, 2),  // out of reach
        sphere_at({0, 0, -0.6f}, 0.5f, 3), // wholly under the ground
        sphere_at({7, 0, 0.5f}, 0.5f, 4),  // off the square by more than its reach
    };
    std::vector<Decal> decals;
    add_ground_decals(ground, occ, decals);
    ASSERT_EQ(decals.size(), 2u);
    // Centred under the body, as wide as the reach sphere's cut through the plane.
    EXPECT_FLOAT_EQ(decals[0].model[3].x, 1.0f);
    EXPECT_FLOAT_EQ(decals[0].model[3].y, 1.0f);
    EXPECT_FLOAT_EQ(decals[0].model[3].z, 0.0f);
    EXPECT_NEAR(glm::length(glm::vec3(decals[0].model[0])), std::sqrt(1.5f * 1.5f - 0.25f), 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec3(decals[1].model[0])), std::sqrt(1.5f * 1.5f - 1.96f), 1e-5f);
    EXPECT_FLOAT_EQ(decals[0].model[2].z, 1.0f); // the plane's normal
}

} // namespace
} // namespace tumble::render
