// The CPU side of instanced drawing: frustum culling, level-of-detail choice, batching, and the
// fitted shadow frustum. No GL needed.
#include "render/batches.h"
#include "render/camera.h"
#include "render/shadow_map.h"

#include "support/measured.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace tumble::render {
namespace {

Frustum camera_frustum() {
    Camera c;
    c.position = {0, -10, 0};
    c.target = {0, 0, 0};
    c.z_far = 100.0f;
    return Frustum::from_view_proj(projection_matrix(c, 16.0f / 9.0f) * view_matrix(c));
}

TEST(Culling, SpheresInsideTouchingAndOutsideTheFrustum) {
    const Frustum f = camera_frustum();
    EXPECT_TRUE(f.intersects_sphere({0, 0, 0}, 0.1f));       // at the target
    EXPECT_FALSE(f.intersects_sphere({0, -20, 0}, 1.0f));    // behind the camera
    EXPECT_FALSE(f.intersects_sphere({0, 200, 0}, 1.0f));    // beyond the far plane
    EXPECT_FALSE(f.intersects_sphere({30, 0, 0}, 1.0f));     // far to the right
    EXPECT_TRUE(f.intersects_sphere({30, 0, 0}, 30.0f));     // ... but big enough to reach in
    EXPECT_FALSE(f.intersects_sphere({0, 0, 30}, 1.0f));     // far above
    EXPECT_TRUE(f.intersects_sphere({0, -10.04f, 0}, 0.1f)); // straddling the near plane
}

TEST(Culling, ShadowCastersOutsideCountWhenTheirShadowCanFallInside) {
    const Frustum f = camera_frustum();
    const glm::vec3 down{0, 0, -1};
    EXPECT_TRUE(f.intersects_swept_sphere({0, 0, 30}, 1.0f, down));   // above, light from above
    EXPECT_FALSE(f.intersects_swept_sphere({0, 0, 30}, 1.0f, -down)); // light from below
    EXPECT_FALSE(f.intersects_swept_sphere({0, 0, -30}, 1.0f, down)); // below, shadow goes down
    EXPECT_FALSE(f.intersects_swept_sphere({60, 0, 0}, 1.0f, down));  // far right: falls outside
}

// Shadows are drawn within shadow_distance of the camera: the view cut there. Cut from the view's
// own planes, it is exactly as wide as the picture however the camera is turned (rebuilding it
// from an aspect ratio read off the view-projection's diagonal made it a fifth as wide for the
// default scene's camera, and the blue ball at the picture's left cast no shadow: issue 14).
TEST(Culling, TheShadowRegionIsTheViewCutAtTheShadowDistance) {
    Camera c; // the default scene's: turned about z and tilted down
    c.position = {1.35f, -2.6f, 1.35f};
    c.target = {0.0f, 0.1f, 0.75f};
    const float aspect = 16.0f / 9.0f;
    const Frustum view = Frustum::from_view_proj(projection_matrix(c, aspect) * view_matrix(c));
    const Frustum cut = view.cut_at(c.position, 50.0f);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(cut.planes[std::size_t(i)], view.planes[std::size_t(i)]);
    const glm::vec3 forward = glm::normalize(c.target - c.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    EXPECT_TRUE(cut.intersects_sphere(c.position + 49.0f * forward, 0.5f));
    EXPECT_FALSE(cut.intersects_sphere(c.position + 51.0f * forward, 0.5f));
    EXPECT_TRUE(view.intersects_sphere(c.position + 51.0f * forward, 0.5f));
    // Just inside the picture's left and right edges, 3 m ahead.
    const float half_width = 3.0f * std::tan(glm::radians(22.5f)) * aspect;
    for (float side : {-0.97f, 0.97f})
        EXPECT_TRUE(
            cut.intersects_sphere(c.position + 3.0f * forward + side * half_width * right, 0.01f))
            << side;
    // The blue ball at frame 0, and the light of the default scene.
    EXPECT_TRUE(cut.intersects_swept_sphere({-0.84f, -0.37f, 1.1f}, 0.1f, {-0.5f, 0.4f, -1.0f}));
}

TEST(LevelOfDetail, SegmentsKeepTheOutlineWithinTheError) {
    for (float r : {2.0f, 10.0f, 50.0f, 300.0f}) {
        const int n = segments_for(r, 0.3f);
        const float error = r * (1.0f - std::cos(3.14159265f / float(n)));
        TUMBLE_MEASURED(error, 0.3f);
        EXPECT_LE(error, 0.3f + 1e-5f) << r;
        // and not wastefully many: one segment fewer would exceed it
        EXPECT_GT(r * (1.0f - std::cos(3.14159265f / float(n - 1))), 0.3f) << r;
    }
    // Long straight edges on a big outline: at most 10 px each.
    EXPECT_EQ(segments_for(100.0f, 0.6f, 10.0f), 63);
    EXPECT_EQ(segments_for(100.0f, 0.6f), 29);
    const std::array<int, 4> levels{12, 24, 48, 64};
    EXPECT_EQ(choose_level(levels, 1.0f, 0.3f), 0u);    // a few pixels: the coarsest
    EXPECT_EQ(choose_level(levels, 30.0f, 0.3f), 1u);   // needs 23
    EXPECT_EQ(choose_level(levels, 5000.0f, 0.3f), 3u); // more than any: the finest
}

TEST(LevelOfDetail, ProjectedRadiusFollowsDistanceAndFieldOfView) {
    // Unit sphere 10 m away, 90 degree field of view, 720 rows: 1/10 of half the height.
    EXPECT_NEAR(projected_radius_px(1.0f, 10.0f, 90.0f, 720), 36.0f, 1e-3f);
    EXPECT_NEAR(projected_radius_px(1.0f, 20.0f, 90.0f, 720), 18.0f, 1e-3f);
}

TEST(Batches, InstancesAreGroupedByMeshInRankOrderAndReuseStorage) {
    GpuMesh* a = reinterpret_cast<GpuMesh*>(0x10); // keys only; never dereferenced here
    GpuMesh* b = reinterpret_cast<GpuMesh*>(0x20);
    BatchList list;
    for (int frame = 0; frame < 2; ++frame) {
        list.clear();
        const InstanceData d = make_instance_data(glm::mat4(1.0f), {1, 0, 0}, {}, false);
        list.add(b, false, 1, d); // the ground: rank 1, drawn last
        list.add(a, true, 0, d);
        list.add(a, true, 0, d);
        list.add(a, false, 0, d); // same mesh, two-sided: its own batch
        list.finish();
        ASSERT_EQ(list.batches().size(), 3u);
        EXPECT_EQ(list.batches()[0].mesh, a);
        EXPECT_EQ(list.batches()[0].count, 2u);
        EXPECT_EQ(list.batches()[1].mesh, a);
        EXPECT_FALSE(list.batches()[1].cull_back);
        EXPECT_EQ(list.batches()[2].mesh, b);
        EXPECT_EQ(list.batches()[2].first, 3u);
        EXPECT_EQ(list.data().size(), 4u);
    }
}

TEST(Batches, InstancesOfABatchAreOrderedNearestFirst) {
    GpuMesh* a = reinterpret_cast<GpuMesh*>(0x10);
    BatchList list;
    for (float distance : {5.0f, 1.0f, 3.0f, 1.0f}) {
        const glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(distance, 0, 0));
        list.add(a, true, 0, make_instance_data(m, {1, 1, 1}, {}, false), distance);
    }
    list.finish();
    ASSERT_EQ(list.data().size(), 4u);
    float last = 0.0f;
    for (const InstanceData& d : list.data()) {
        EXPECT_GE(d.model[3].x, last);
        last = d.model[3].x;
    }
}

TEST(Batches, InstanceDataCarriesColourMaterialAndNoOccluder) {
    const glm::mat4 squash = glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, 0.25f));
    const InstanceData d = make_instance_data(squash, {0.2f, 0.4f, 0.6f}, {0.0f, 0.7f, 1.0f}, true);
    EXPECT_FLOAT_EQ(d.material.w, 1.0f); // gloss = 1 - roughness: a polished surface
    // No occluder yet: each slot holds a unit sphere 1 km away, whose occlusion has faded to 0.
    for (std::size_t k = 0; k < 6; ++k) EXPECT_GE(std::abs(d.occluders[k].w), 999.0f);
    // sRGB in, linear out (IEC 61966-2-1: 0.2 -> 0.0331, 0.4 -> 0.1329, 0.6 -> 0.3185).
    EXPECT_NEAR(d.color.r, 0.03310f, 1e-4f);
    EXPECT_NEAR(d.color.g, 0.13287f, 1e-4f);
    EXPECT_NEAR(d.color.b, 0.31855f, 1e-4f);
    EXPECT_EQ(d.color.a, 1.0f);             // checker
    EXPECT_FLOAT_EQ(d.material.x, 1025.0f); // roughness 0: sharpest highlight
    EXPECT_FLOAT_EQ(d.material.y, 0.7f);
    EXPECT_FLOAT_EQ(d.material.z, 1.0f);
    EXPECT_FLOAT_EQ(shininess_from_roughness(1.0f), 2.0f);
}

// Every caster lands inside the fitted light frustum, and small moves do not change its size.
TEST(ShadowFit, CastersAreInsideAndTheFrustumIsStable) {
    const glm::vec3 light{-0.5f, 0.4f, -1.0f};
    std::vector<glm::vec4> casters{{0, 0, 1, 0.3f}, {2, 1, 0.5f, 0.2f}, {-1, 2, 3, 0.5f}};
    const LightFrame f = fit_light_frame(light, casters, 1024);
    ASSERT_FALSE(f.empty);
    for (const glm::vec4& c : casters) {
        for (int axis = 0; axis < 3; ++axis)
            for (float sign : {-1.0f, 1.0f}) {
                glm::vec3 p(c);
                p[axis] += sign * c.w;
                const glm::vec4 clip = f.view_proj * glm::vec4(p, 1.0f);
                for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(clip[k]), 1.0f) << k;
            }
    }
    casters[0].x += 0.001f; // a small move: same size, centre moves by whole texels only
    const LightFrame g = fit_light_frame(light, casters, 1024);
    EXPECT_FLOAT_EQ(g.texel_size, f.texel_size);
    const glm::vec4 o1 = f.view_proj * glm::vec4(0, 0, 0, 1),
                    o2 = g.view_proj * glm::vec4(0, 0, 0, 1);
    const float shift_texels = (o2.x - o1.x) * 0.5f * 1024.0f;
    EXPECT_NEAR(shift_texels, std::round(shift_texels), 1e-2f);
    EXPECT_TRUE(fit_light_frame(light, {}, 1024).empty);
}

// The map is as small as the texel target allows: about 1.2 cm texels, at most max_map_size.
TEST(ShadowFit, MapSizeFollowsTheCastersExtent) {
    const glm::vec3 light{0, 0, -1};
    const std::vector<glm::vec4> small{{0, 0, 1, 0.5f}};  // 1 m across
    const std::vector<glm::vec4> large{{0, 0, 1, 10.0f}}; // 20 m across
    const LightFrame s = fit_light_frame(light, small, 1024, 0.012f);
    const LightFrame l = fit_light_frame(light, large, 1024, 0.012f);
    EXPECT_EQ(s.map_size, 128); // 1.02 m / 0.012 m = 85 -> 128 texels
    EXPECT_LE(s.texel_size, 0.012f);
    EXPECT_EQ(l.map_size, 1024); // would need 2048: capped
    EXPECT_GT(l.texel_size, 0.012f);
}

} // namespace
} // namespace tumble::render
