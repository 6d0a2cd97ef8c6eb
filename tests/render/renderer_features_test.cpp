// Shadows, anti-aliasing, materials, body axes and the text overlay each change the picture the
// way they should, and only where they should.
#include "render/png_io.h"
#include "render/renderer.h"

#include "support/measured.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

namespace tumble::render {
namespace {

int luma(const Image& img, int x, int y) {
    const std::uint8_t* p = img.row(y) + 3 * x;
    return (2 * p[0] + 5 * p[1] + p[2]) / 8;
}

// Saved beside the other test artifacts, to look at when a test fails.
void save(const Image& img, const std::string& name) {
    write_png(std::string(TUMBLE_TEST_ARTIFACTS) + "/features_" + name + ".png", img);
}

// Looking down at a ball hovering over the ground, with the light straight from above.
SceneView ball_over_ground() {
    SceneView v;
    v.camera.position = {0.0f, -4.0f, 4.0f};
    v.camera.target = {0.0f, 0.0f, 0.0f};
    v.light.direction = {0.0f, 0.0f, -1.0f};
    Instance ground{MeshKind::Plane,
                    glm::scale(glm::mat4(1.0f), glm::vec3(10.0f, 10.0f, 1.0f)),
                    {0.8f, 0.8f, 0.8f}};
    ground.material = {0.9f, 0.1f, 0.0f};
    v.instances.push_back(ground);
    v.instances.push_back(
        {MeshKind::Sphere,
         glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 1.0f)), glm::vec3(0.4f)),
         {0.9f, 0.2f, 0.1f}});
    return v;
}

// Screen position of a world point.
glm::ivec2 to_pixel(const SceneView& v, glm::vec3 p, int w, int h);

TEST(RendererFeatures, ShadowFallsUnderTheBallAndOnlyWithShadowsOn) {
    const SceneView view = ball_over_ground();
    RenderOptions o{160, 120};
    o.samples = 1;
    Renderer shadowed(o);
    o.shadows = false;
    Renderer plain(o);
    Image a, b;
    shadowed.draw(view, a);
    plain.draw(view, b);
    save(a, "shadowed");
    save(b, "unshadowed");
    const glm::ivec2 under = to_pixel(view, {1.0f, 0.0f, 0.0f}, 160, 120);
    const glm::ivec2 beside = to_pixel(view, {-1.0f, 0.0f, 0.0f}, 160, 120);
    // The spot under the ball is hidden from the camera by nothing (the ball is seen from the
    // side, its shadow straight below): darker with shadows than without; open ground is the
    // same either way.
    const int darkening = luma(b, under.x, under.y) - luma(a, under.x, under.y);
    TUMBLE_MEASURED(darkening, 40);
    EXPECT_GT(darkening, 40);
    EXPECT_EQ(luma(a, beside.x, beside.y), luma(b, beside.x, beside.y));
}

TEST(RendererFeatures, MultisamplingSoftensEdges) {
    SceneView view = ball_over_ground();
    RenderOptions o{160, 120};
    o.shadows = false;
    o.samples = 1;
    Renderer aliased(o);
    o.samples = 4;
    Renderer smooth(o);
    EXPECT_EQ(smooth.options().samples, 4);
    Image a, b;
    aliased.draw(view, a);
    smooth.draw(view, b);
    // Along a row through the ball, MSAA adds in-between colours at the two edges.
    const int y = to_pixel(view, {1.0f, 0.0f, 1.0f}, 160, 120).y;
    auto distinct = [y](const Image& img) {
        std::set<int> colours;
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.row(y) + 3 * x;
            colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
        }
        return colours.size();
    };
    EXPECT_GT(distinct(b), distinct(a));
    int differing = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) differing += a.rgb[i] != b.rgb[i];
    EXPECT_GT(differing, 50);                     // the edges changed ...
    EXPECT_LT(differing, int(a.rgb.size()) / 10); // ... and little else
}

TEST(RendererFeatures, MetalAndRoughnessChangeTheBall) {
    SceneView view = ball_over_ground();
    Renderer r({160, 120});
    Image plastic, metal, matte;
    r.draw(view, plastic);
    view.instances[1].material = {0.3f, 1.0f, 1.0f};
    r.draw(view, metal);
    view.instances[1].material = {1.0f, 0.0f, 0.0f};
    r.draw(view, matte);
    save(plastic, "plastic");
    save(metal, "metal");
    save(matte, "matte");
    const glm::ivec2 c = to_pixel(view, {1.0f, 0.0f, 1.0f}, 160, 120);
    // The ball is red; a white highlight raises green. Over the pixels that are clearly red on
    // the matte ball (no highlight there), the plastic one is much greener somewhere.
    int most = 0;
    for (int y = c.y - 12; y <= c.y + 12; ++y)
        for (int x = c.x - 12; x <= c.x + 12; ++x) {
            const std::uint8_t* m = matte.row(y) + 3 * x;
            const std::uint8_t* p = plastic.row(y) + 3 * x;
            if (m[0] > m[1] + 80) most = std::max(most, int(p[1]) - int(m[1]));
        }
    TUMBLE_MEASURED(most, 60);
    EXPECT_GT(most, 60);
    EXPECT_NE(plastic.rgb, metal.rgb);
}

TEST(RendererFeatures, AxesAddRedGreenBlueRods) {
    SceneView view = ball_over_ground();
    view.instances[1].color = {0.5f, 0.5f, 0.5f};
    Renderer r({320, 240});
    Image without, with;
    r.draw(view, without);
    view.instances[1].axes = true;
    r.draw(view, with);
    save(with, "axes");
    // The x rod pokes out of the ball towards +x (screen right of the ball), red.
    const glm::ivec2 tip = to_pixel(view, {1.0f + 0.5f, 0.0f, 1.0f}, 320, 240);
    const std::uint8_t* p = with.row(tip.y) + 3 * tip.x;
    EXPECT_GT(p[0], p[1] + 60) << int(p[0]) << " " << int(p[1]) << " " << int(p[2]);
    EXPECT_NE(with.rgb, without.rgb);
}

TEST(RendererFeatures, OverlayDrawsTextOnAPanelInTheTopLeftOnly) {
    SceneView view = ball_over_ground();
    Renderer r({320, 180});
    Image without, with;
    r.draw(view, without);
    view.overlay = {"t 1.250 s", "E 6.787741 J"};
    r.draw(view, with);
    save(with, "overlay");
    int changed_left = 0, changed_right = 0, white = 0;
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x) {
            const std::uint8_t* a = without.row(y) + 3 * x;
            const std::uint8_t* b = with.row(y) + 3 * x;
            const bool changed = a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
            (x < 160 && y < 90 ? changed_left : changed_right) += changed;
            white += changed && b[0] > 180 && b[1] > 180 && b[2] > 180;
        }
    EXPECT_GT(changed_left, 1000); // the panel
    EXPECT_EQ(changed_right, 0);
    EXPECT_GT(white, 20); // glyph strokes: changed, yet bright
    Image again;
    r.draw(view, again);
    EXPECT_EQ(again.rgb, with.rgb);
}

glm::ivec2 to_pixel(const SceneView& v, glm::vec3 p, int w, int h) {
    const glm::mat4 view = glm::lookAt(v.camera.position, v.camera.target, v.camera.up);
    const glm::mat4 proj = glm::perspective(glm::radians(v.camera.fov_y_deg), float(w) / float(h),
                                            v.camera.z_near, v.camera.z_far);
    const glm::vec4 clip = proj * view * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {int((ndc.x * 0.5f + 0.5f) * float(w)), int((0.5f - ndc.y * 0.5f) * float(h))};
}

} // namespace
} // namespace tumble::render
