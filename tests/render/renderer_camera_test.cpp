// The camera matrices put the target in the middle of the screen, with world up on screen up.
#include "render/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::render {
namespace {

glm::vec3 to_ndc(const Camera& c, glm::vec3 world) {
    const glm::vec4 clip =
        projection_matrix(c, 16.0f / 9.0f) * view_matrix(c) * glm::vec4(world, 1);
    return glm::vec3(clip) / clip.w;
}

TEST(RendererCamera, TargetIsAtScreenCentreAndUpIsUp) {
    const Camera c; // default: (4,-6,3) looking at (0,0,1)
    const glm::vec3 centre = to_ndc(c, c.target);
    EXPECT_NEAR(centre.x, 0.0f, 1e-5f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-5f);
    EXPECT_GT(centre.z, -1.0f); // inside the depth range
    EXPECT_LT(centre.z, 1.0f);
    EXPECT_GT(to_ndc(c, c.target + glm::vec3(0, 0, 0.5f)).y, 0.0f); // above the target: up
}

TEST(RendererCamera, LookingStraightDownStillGivesAFiniteView) {
    Camera c;
    c.position = {0, 0, 10};
    c.target = {0, 0, 0}; // parallel to up = +z
    const glm::mat4 v = view_matrix(c);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(v[i][j]));
    const glm::vec3 centre = to_ndc(c, c.target);
    EXPECT_NEAR(centre.x, 0.0f, 1e-5f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-5f);
}

} // namespace
} // namespace tumble::render
