// Issue 14's grounded look, each effect checked against what it should do in physical terms:
//   - ambient occlusion on the ground falls off as the form factor of a sphere, r^3 / d^3;
//   - a body darkens the ambient light of another body near it, and of nothing out of reach;
//   - soft shadows harden towards the contact: the penumbra widens with the distance the light
//     travels from the caster's edge to the ground;
//   - a reflecting floor shows a body's mirror image where the mirror puts it, and nothing else.
#include "render/png_io.h"
#include "render/renderer.h"

#include "support/measured.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tumble::render {
namespace {

void save(const Image& img, const std::string& name) {
    write_png(std::string(TUMBLE_TEST_ARTIFACTS) + "/soft_lighting_" + name + ".png", img);
}

glm::ivec2 to_pixel(const Camera& c, glm::vec3 p, int w, int h) {
    const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
    const glm::mat4 proj =
        glm::perspective(glm::radians(c.fov_y_deg), float(w) / float(h), c.z_near, c.z_far);
    const glm::vec4 clip = proj * view * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {int((ndc.x * 0.5f + 0.5f) * float(w)), int((0.5f - ndc.y * 0.5f) * float(h))};
}

// The pixel at p; a point the camera does not see is a mistake in the test.
const std::uint8_t* pixel(const Image& img, glm::ivec2 p) {
    if (p.x < 0 || p.y < 0 || p.x >= img.width || p.y >= img.height)
        throw std::out_of_range("pixel " + std::to_string(p.x) + "," + std::to_string(p.y) +
                                " is outside the image");
    return img.row(p.y) + 3 * p.x;
}

// sRGB (IEC 61966-2-1) 8-bit value -> linear light.
double linear(std::uint8_t v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

int luma(const Image& img, glm::ivec2 p) {
    const std::uint8_t* q = pixel(img, p);
    return (2 * q[0] + 5 * q[1] + q[2]) / 8;
}

Instance ground(float half = 10.0f) {
    Instance g{MeshKind::Plane,
               glm::scale(glm::mat4(1.0f), glm::vec3(half, half, 1.0f)),
               {0.75f, 0.75f, 0.72f}};
    g.material = {0.9f, 0.1f, 0.0f};
    g.body = 0;
    return g;
}

Instance sphere(glm::vec3 c, float r, glm::vec3 colour, int body) {
    Instance s{MeshKind::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), c), glm::vec3(r)),
               colour};
    s.body = body;
    return s;
}

// The view drawn with one effect on and off, everything else as `o` says, one sample per pixel
// (each pixel one point of one surface).
struct OnOff {
    Image on, off;
};
OnOff on_and_off(const SceneView& v, RenderOptions o, bool RenderOptions::*effect) {
    o.samples = 1;
    OnOff out;
    for (const bool state : {true, false}) {
        o.*effect = state;
        Renderer(o).draw(v, state ? out.on : out.off);
    }
    return out;
}

TEST(SoftLighting, GroundOcclusionFallsOffAsTheFormFactorOfTheSphere) {
    // A ball of radius r resting on the ground, seen from straight above. A ground point at
    // horizontal distance x from the contact sees the ball's centre at d = sqrt(x^2 + r^2), at
    // cos(theta) = r / d from its normal: the ball hides cos(theta) r^2 / d^2 = r^3 / d^3 of
    // its sky. The decal darkens by kStrength = 0.6 of that (ao_decal.frag): in linear light
    // the ground keeps 1 - 0.6 r^3 / d^3.
    const float r = 0.5f;
    const glm::vec3 c(0.25f, 0.25f, r); // the middle of a checker square
    SceneView v;
    v.camera.position = {c.x, c.y, 5.0f};
    v.camera.target = {c.x, c.y, 0.0f};
    v.camera.up = {0.0f, 1.0f, 0.0f};
    v.camera.fov_y_deg = 30.0f;
    v.instances = {ground(), sphere(c, r, {0.8f, 0.3f, 0.2f}, 1)};
    RenderOptions o{320, 320};
    o.shadows = false;
    const auto [with, without] = on_and_off(v, o, &RenderOptions::ambient_occlusion);
    save(with, "ao_sphere");
    save(without, "ao_sphere_off");
    double worst = 0.0;
    for (float f : {1.3f, 1.5f, 1.7f}) { // x / r: nearer is hidden under the ball from above
        for (glm::vec3 dir : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, -1, 0)}) {
            const glm::vec3 p = glm::vec3(c.x, c.y, 0.0f) + f * r * dir;
            const glm::ivec2 px = to_pixel(v.camera, p, 320, 320);
            const double kept = linear(pixel(with, px)[1]) / linear(pixel(without, px)[1]);
            const double expected = 1.0 - 0.6 / std::pow(f * f + 1.0, 1.5);
            worst = std::max(worst, std::abs(kept - expected));
            EXPECT_NEAR(kept, expected, 0.03)
                << "x = " << f << " r towards " << dir.x << "," << dir.y;
        }
    }
    TUMBLE_MEASURED(worst, 0.03);
    // Out of reach (3 radii in the ball's unit space), nothing changes.
    const glm::ivec2 far = to_pixel(v.camera, {c.x + 1.1f, c.y + 1.1f, 0.0f}, 320, 320);
    EXPECT_EQ(luma(with, far), luma(without, far));
}

TEST(SoftLighting, ABodyDarkensTheAmbientLightOfABodyNearItAndOfNothingBeyond) {
    // A ball hovering 0.05 m over a slab. A point on the slab's top 0.3 m to the side of the
    // ball's foot sees the ball (r = 0.2 at height 0.25 above it) at l = 1.95 radii: it loses
    // cos(theta) / l^2 = 0.17 of its sky light. 0.6 m to the side, l = 3.25: out of reach.
    SceneView v;
    v.camera.position = {0.0f, -2.5f, 2.5f};
    v.camera.target = {0.0f, 0.0f, 0.2f};
    Instance slab{MeshKind::Box,
                  glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 0.1f)),
                             glm::vec3(0.9f, 0.9f, 0.1f)),
                  {0.7f, 0.7f, 0.7f}};
    slab.body = 1;
    v.instances = {ground(), slab, sphere({0.0f, 0.3f, 0.45f}, 0.2f, {0.2f, 0.4f, 0.8f}, 2)};
    RenderOptions o{320, 320};
    o.shadows = false;
    const auto [with, without] = on_and_off(v, o, &RenderOptions::ambient_occlusion);
    save(with, "ao_slab");
    const glm::ivec2 near = to_pixel(v.camera, {0.3f, 0.3f, 0.2f}, 320, 320);
    const glm::ivec2 far = to_pixel(v.camera, {0.6f, -0.3f, 0.2f}, 320, 320);
    const int darkening = luma(without, near) - luma(with, near);
    TUMBLE_MEASURED(darkening, 2);
    EXPECT_GE(darkening, 2);
    EXPECT_EQ(luma(with, far), luma(without, far));
}

// Pixels over which the ground's luma crosses from 10% to 90% of the way between its darkest
// and brightest along a column of the image, rows [top, bottom).
int edge_width(const Image& img, int column, int top, int bottom) {
    int lo = 255, hi = 0;
    for (int y = top; y < bottom; ++y) {
        lo = std::min(lo, luma(img, {column, y}));
        hi = std::max(hi, luma(img, {column, y}));
    }
    const double a = lo + 0.1 * (hi - lo), b = lo + 0.9 * (hi - lo);
    int n = 0;
    for (int y = top; y < bottom; ++y) {
        const int l = luma(img, {column, y});
        n += l > a && l < b;
    }
    return n;
}

TEST(SoftLighting, ShadowsHardenTowardsTheContact) {
    // A plank standing on the ground, lit at 45 degrees along +x: its shadow runs from its
    // foot along +x. The side edge of the shadow at distance s from the foot is thrown by the
    // plank's edge at height s, s sqrt(2) away along the light, so the penumbra there is
    // 2 tan(angle / 2) s sqrt(2) wide: a hair at the foot, wide at the far end.
    SceneView v;
    v.light.direction = {1.0f, 0.0f, -1.0f};
    v.light.angle_deg = 2.5f;
    v.camera.position = {1.0f, 0.62f, 3.0f};
    v.camera.target = {1.0f, 0.62f, 0.0f};
    v.camera.up = {0.0f, 1.0f, 0.0f};
    v.camera.fov_y_deg = 30.0f;
    Instance plank{MeshKind::Box,
                   glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.12f, 1.0f)),
                              glm::vec3(0.05f, 0.5f, 1.0f)),
                   {0.6f, 0.5f, 0.4f}};
    plank.body = 1;
    v.instances = {ground(), plank}; // its shadow's side edge: y = 0.62, between checker lines
    RenderOptions o{900, 900};
    o.ambient_occlusion = false;
    const auto [soft, hard] = on_and_off(v, o, &RenderOptions::soft_shadows);
    save(soft, "penumbra_soft");
    save(hard, "penumbra_hard");
    auto widths = [&](const Image& img) {
        std::array<int, 2> w{};
        int i = 0;
        for (float s : {0.35f, 1.45f}) { // distances from the foot (away from checker lines)
            const glm::ivec2 top = to_pixel(v.camera, {s, 0.70f, 0.0f}, 900, 900);
            const glm::ivec2 bottom = to_pixel(v.camera, {s, 0.54f, 0.0f}, 900, 900);
            EXPECT_TRUE(top.x >= 0 && top.x < 900 && top.y >= 0 && bottom.y <= 900);
            w[std::size_t(i++)] = edge_width(img, top.x, top.y, bottom.y);
        }
        return w;
    };
    const auto s = widths(soft), h = widths(hard);
    const double soft_ratio = double(s[1]) / std::max(1, s[0]);
    const double hard_ratio = double(h[1]) / std::max(1, h[0]);
    std::printf("[measured] penumbra px near/far: soft %d/%d, hard %d/%d\n", s[0], s[1], h[0],
                h[1]);
    TUMBLE_MEASURED(soft_ratio, 1.4);
    TUMBLE_MEASURED(hard_ratio, 1.25);
    EXPECT_GE(soft_ratio, 1.4); // far edge wider than the near one
    EXPECT_LE(hard_ratio, 1.25);
    EXPECT_GE(hard_ratio, 0.8);
    EXPECT_LE(s[0], h[0] + 1); // at the foot as sharp as a hard shadow
}

TEST(SoftLighting, AReflectingFloorShowsTheMirrorImageAndNothingElse) {
    // A red ball hovering over a grey floor. Mirrored in the floor (z -> -z) its centre goes to
    // (0, 0, -0.6): with reflections on, that point of the floor turns red; elsewhere nothing
    // changes, floor or sky.
    SceneView v;
    v.camera.position = {0.0f, -4.0f, 1.0f};
    v.camera.target = {0.0f, 0.0f, 0.2f};
    v.instances = {ground(), sphere({0.0f, 0.0f, 0.6f}, 0.3f, {0.9f, 0.1f, 0.1f}, 1)};
    RenderOptions o{320, 240};
    o.ambient_occlusion = false;
    const auto [mirror, plain] = on_and_off(v, o, &RenderOptions::reflections);
    save(mirror, "reflection");
    auto redness = [](const Image& img, glm::ivec2 p) {
        return int(pixel(img, p)[0]) - int(pixel(img, p)[1]);
    };
    const glm::ivec2 image = to_pixel(v.camera, {0.0f, 0.0f, -0.6f}, 320, 240);
    const int gained = redness(mirror, image) - redness(plain, image);
    TUMBLE_MEASURED(gained, 20);
    EXPECT_GE(gained, 20);
    for (glm::vec3 p : {glm::vec3(2.0f, 1.0f, 0.0f), glm::vec3(0.0f, 50.0f, 8.0f)}) {
        const glm::ivec2 q = to_pixel(v.camera, p, 320, 240);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(pixel(mirror, q)[k], pixel(plain, q)[k]);
    }
}

} // namespace
} // namespace tumble::render
