// Every body of every built-in scene casts a shadow on the ground (issue 14: the default scene's
// blue ball cast none). Frame 0 of each scene is drawn with shadows on and off, and for each
// dynamic body the ground pixels its shadow must cover are darker with them on.
//
// Which pixels those are is worked out here from the light's direction and each body's shape and
// pose, not from the renderer's shadow map: a pixel's ray from the camera meets the ground at Q,
// and Q is in a body's shadow when the ray from Q towards the light meets the body
// (light_rays.h). Only pixels whose verdict is unambiguous count:
//   - the camera sees the ground there (the frame without shadows and the ground drawn alone
//     agree exactly on the pixel), inside the ground square's unfogged four fifths;
//   - the rays from Q and from 8 points around it (a margin away: shadow edges are soft) all meet
//     this body, and a depth or more from the ground: nearer the body's contact, a shadow map's
//     depth offset may let light through, which is a different matter from a missing shadow;
//   - none of those rays meets another drawn body (whose shadow would darken Q anyway).
// Bodies with too few such pixels in the whole frame (their shadows fall on or among other
// bodies: stacks, the sphere-rain block) are drawn again in groups whose shadows lie apart,
// alone with the ground, and those still short of pixels (another of the group stands between
// the camera and the shadow) alone. The light's frustum is then fitted to the group, not to the
// frame, but whether a caster is kept does not depend on the others.
// Every dynamic body whose shadow falls in view is judged: one whose shadow, cast with the body
// alone on the ground, covers at least kMinPixels ground pixels the camera sees past the body
// (by the rays above, without the renderer). A body left out is one whose shadow is out of the
// picture, in the ground's fading rim, or hidden behind the body itself; the count says so.
#include "app/run/auto_camera.h"
#include "app/run/simulation.h"
#include "app/scene/scene.h"
#include "app/view/view_builder.h"
#include "render/camera.h"
#include "render/png_io.h"
#include "render/renderer.h"

#include "light_rays.h"
#include "support/measured.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace tumble::app {
namespace {

using render::test::BodyShape;

constexpr int kWidth = 640, kHeight = 360;
// Clear of the soft edge and of the contact: these, or these fractions of the body's bounding
// radius when smaller (a 6 cm spinning top gets proportionally smaller margins).
constexpr double kMargin = 0.02, kMarginPerSize = 0.15; // m, across the ground
constexpr double kDepth = 0.05, kDepthPerSize = 0.25;   // m, from the ground along the light
constexpr int kMinPixels = 4;                           // fewer: not judged in that drawing
constexpr double kMinDarkening = 0.2; // 1 - luma(shadows on) / luma(off), over a body's pixels

struct Ground {
    glm::dvec3 point, normal, axis_x, axis_y;
    double half_extent;
};

// Frame 0 of a scene: what is drawn, and every body but the grounds as a shape (a caster).
struct Frame {
    Scene scene;
    render::SceneView view;
    std::vector<BodyShape> casters;
    std::vector<int> body;                         // casters[k] is body body[k]
    std::vector<bool> dynamic;                     // per caster
    std::vector<std::array<std::size_t, 2>> drawn; // per caster: its instances [first, last)
    std::vector<Ground> grounds;
    glm::dvec3 to_light{0.0}; // unit
};

Frame frame_zero(const std::string& name) {
    Frame f;
    f.scene = load_scene_argument(name);
    // The camera the scene is drawn with (camera.auto is chosen by a pre-pass over the run).
    frame_automatically(f.scene,
                        make_timeline(f.scene.world.dt, f.scene.duration, f.scene.render.fps));
    const Simulation sim = make_simulation(f.scene, f.scene.world.dt);
    build_view(f.scene, sim.model, sim.state, f.view);
    f.to_light = -glm::normalize(glm::dvec3(f.view.light.direction));
    std::size_t instance = 0;
    for (int i = 0; i < sim.model.body_count(); ++i) {
        const physics::Shape& s = sim.model.shape[std::size_t(i)];
        const BodyLook& look = f.scene.looks[std::size_t(i)];
        const bool mesh = s.kind == physics::ShapeKind::Mesh;
        const BodyShape b =
            render::test::body_shape(s, physics::body_pose(sim.model, sim.state, i),
                                     mesh ? f.scene.meshes[look.mesh_id].get() : nullptr);
        // build_view draws a capsule as a cylinder and two end spheres, any other body as one.
        const std::size_t count = s.kind == physics::ShapeKind::Capsule ? 3 : 1;
        if (s.kind == physics::ShapeKind::Plane) {
            f.grounds.push_back(
                {b.position, b.rotation[2], b.rotation[0], b.rotation[1], 0.5 * look.plane_extent});
        } else {
            f.casters.push_back(b);
            f.body.push_back(i);
            f.dynamic.push_back(sim.model.motion[std::size_t(i)] == physics::Motion::Dynamic);
            f.drawn.push_back({instance, instance + count});
        }
        instance += count;
    }
    EXPECT_EQ(instance, f.view.instances.size()) << "build_view's instances per body changed";
    return f;
}

// Where a pixel's ray from the eye first meets a ground square's inner four fifths (the outer
// fifth fades into the sky, lit.frag); `ground` is null where it meets none.
struct GroundPixel {
    const Ground* ground = nullptr;
    glm::dvec3 q{0.0};
    glm::dvec3 dir{0.0}; // unit, from the eye; q = eye + t dir
    double t = 0.0;
};

std::vector<GroundPixel> ground_pixels(const Frame& f) {
    const glm::dmat4 inv = glm::inverse(
        glm::dmat4(render::projection_matrix(f.view.camera, float(kWidth) / float(kHeight)) *
                   render::view_matrix(f.view.camera)));
    const glm::dvec3 eye(f.view.camera.position);
    std::vector<GroundPixel> out(std::size_t(kWidth * kHeight));
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec2 ndc((x + 0.5) / kWidth * 2.0 - 1.0, 1.0 - (y + 0.5) / kHeight * 2.0);
            const glm::dvec4 a = inv * glm::dvec4(ndc, -1.0, 1.0);
            const glm::dvec4 b = inv * glm::dvec4(ndc, 1.0, 1.0);
            const glm::dvec3 dir = glm::normalize(glm::dvec3(b) / b.w - glm::dvec3(a) / a.w);
            double nearest = 1e300;
            for (const Ground& g : f.grounds) {
                const double t = glm::dot(g.normal, g.point - eye) / glm::dot(g.normal, dir);
                const glm::dvec3 p = eye + t * dir - g.point;
                const double lx = glm::dot(p, g.axis_x), ly = glm::dot(p, g.axis_y);
                if (t > 0.0 && t < nearest &&
                    std::max(std::abs(lx), std::abs(ly)) < 0.8 * g.half_extent) {
                    nearest = t;
                    out[std::size_t(y * kWidth + x)] = {&g, p + g.point, dir, t};
                }
            }
        }
    }
    return out;
}

double margin(const BodyShape& b) {
    return std::min(kMargin, kMarginPerSize * b.bound);
}

// The shadow of the body's bounding sphere on ground g: a circle about the shadow of its centre
// holding the ellipse of half axes bound and bound / cos(light, normal), widened by the margin.
std::pair<glm::dvec3, double> shadow_circle(const BodyShape& b, const Ground& g,
                                            glm::dvec3 to_light) {
    const double cos_light = std::max(glm::dot(g.normal, to_light), 1e-6);
    const double lift = glm::dot(g.normal, b.position - g.point) / cos_light;
    return {b.position - lift * to_light, b.bound / cos_light + 2.0 * margin(b)};
}

// Q and 8 points the body's margin around it, in the ground plane.
std::array<glm::dvec3, 9> around(const GroundPixel& p, const BodyShape& b) {
    std::array<glm::dvec3, 9> out{p.q};
    for (int k = 0; k < 8; ++k) {
        const double a = k * glm::pi<double>() / 4.0;
        out[std::size_t(k) + 1] =
            p.q + margin(b) * (std::cos(a) * p.ground->axis_x + std::sin(a) * p.ground->axis_y);
    }
    return out;
}

// Whether the rays from all the points towards the light meet the body, far enough along.
bool deep_in_shadow(const BodyShape& b, const std::array<glm::dvec3, 9>& points,
                    glm::dvec3 to_light) {
    for (const glm::dvec3& p : points) {
        const double entry = render::test::ray_entry(b, p, to_light);
        if (entry < std::min(kDepth, kDepthPerSize * b.bound) || entry == render::test::kMiss)
            return false;
    }
    return true;
}

bool in_no_shadow_of(const BodyShape& b, const std::array<glm::dvec3, 9>& points,
                     glm::dvec3 to_light) {
    for (const glm::dvec3& p : points)
        if (render::test::blocks(b, p, to_light)) return false;
    return true;
}

// Ground pixels in each caster's shadow that the camera sees past the caster itself, the caster
// alone on the ground: whether its shadow falls in view, from the rays alone.
std::vector<int> shadow_pixels_in_view(const Frame& f, const std::vector<GroundPixel>& pixels) {
    std::vector<int> count(f.casters.size(), 0);
    const glm::dvec3 eye(f.view.camera.position);
    for (std::size_t i = 0; i < f.casters.size(); ++i) {
        if (!f.dynamic[i]) continue;
        const BodyShape& b = f.casters[i];
        std::vector<std::pair<glm::dvec3, double>> circles; // on each ground
        for (const Ground& g : f.grounds) circles.push_back(shadow_circle(b, g, f.to_light));
        for (const GroundPixel& p : pixels) {
            if (!p.ground) continue;
            const auto [centre, radius] = circles[std::size_t(p.ground - f.grounds.data())];
            const glm::dvec3 d = p.q - centre;
            if (glm::dot(d, d) > radius * radius) continue;
            if (render::test::ray_entry(b, eye, p.dir) < p.t) continue; // the body hides it
            count[i] += deep_in_shadow(b, around(p, b), f.to_light);
        }
    }
    return count;
}

double luma(const render::Image& img, std::size_t pixel) {
    const std::uint8_t* p = img.rgb.data() + 3 * pixel;
    return (2.0 * p[0] + 5.0 * p[1] + p[2]) / 8.0;
}

// A body's judged pixels: summed luma with shadows on and off.
struct Tally {
    int pixels = 0;
    double on = 0.0, off = 0.0;
    void add(double lit_on, double lit_off) { ++pixels, on += lit_on, off += lit_off; }
    double darkening() const { return 1.0 - on / off; }
};

struct Renderers {
    render::Renderer shadowed, plain;
    render::Image ground_off; // the grounds alone, without shadows
};

// Draws the grounds and `drawn` (caster indices) with shadows on and off, and tallies each of
// them on the pixels where the camera sees the ground and only that body's shadow can fall.
std::vector<Tally> judge(const Frame& f, const std::vector<std::size_t>& drawn,
                         const std::vector<GroundPixel>& pixels, Renderers& r,
                         const std::string& save_as = "") {
    render::SceneView view = f.view;
    std::erase_if(view.instances,
                  [](const render::Instance& in) { return in.mesh != render::MeshKind::Plane; });
    for (std::size_t i : drawn)
        for (std::size_t k = f.drawn[i][0]; k < f.drawn[i][1]; ++k)
            view.instances.push_back(f.view.instances[k]);
    render::Image on, off;
    r.shadowed.draw(view, on);
    r.plain.draw(view, off);
    if (!save_as.empty()) {
        render::write_png(save_as + "_on.png", on);
        render::write_png(save_as + "_off.png", off);
    }
    std::vector<std::pair<glm::dvec3, double>> circles; // on the first ground
    for (std::size_t i : drawn)
        circles.push_back(shadow_circle(f.casters[i], f.grounds.front(), f.to_light));
    std::vector<Tally> tally(drawn.size());
    for (std::size_t px = 0; px < pixels.size(); ++px) {
        const GroundPixel& p = pixels[px];
        const auto rgb = [px](const render::Image& img) { return img.rgb.begin() + 3 * long(px); };
        if (!p.ground || !std::equal(rgb(off), rgb(off) + 3, rgb(r.ground_off)))
            continue; // no ground, or a body covers it here
        for (std::size_t a = 0; a < drawn.size(); ++a) {
            const BodyShape& b = f.casters[drawn[a]];
            const auto [centre, radius] = p.ground == &f.grounds.front()
                                              ? circles[a]
                                              : shadow_circle(b, *p.ground, f.to_light);
            const glm::dvec3 d = p.q - centre;
            if (glm::dot(d, d) > radius * radius) continue;
            const std::array<glm::dvec3, 9> points = around(p, b);
            if (!deep_in_shadow(b, points, f.to_light)) continue;
            bool alone = true;
            for (std::size_t c = 0; c < drawn.size() && alone; ++c)
                alone = c == a || in_no_shadow_of(f.casters[drawn[c]], points, f.to_light);
            if (alone) tally[a].add(luma(on, px), luma(off, px));
        }
    }
    return tally;
}

// `bodies` split into groups whose shadows cannot touch one another (greedy, in order).
std::vector<std::vector<std::size_t>> apart(const Frame& f,
                                            const std::vector<std::size_t>& bodies) {
    const auto circle = [&](std::size_t i) {
        return shadow_circle(f.casters[i], f.grounds.front(), f.to_light);
    };
    std::vector<std::vector<std::size_t>> groups;
    for (std::size_t i : bodies) {
        const auto [ci, ri] = circle(i);
        const auto fits = [&](const std::vector<std::size_t>& g) {
            return std::all_of(g.begin(), g.end(), [&](std::size_t j) {
                const auto [cj, rj] = circle(j);
                return glm::length(ci - cj) >= ri + rj;
            });
        };
        const auto g = std::find_if(groups.begin(), groups.end(), fits);
        if (g != groups.end())
            g->push_back(i);
        else
            groups.push_back({i});
    }
    return groups;
}

class EveryBodyCastsAShadow : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryBodyCastsAShadow, GroundUnderEachBodyDarkensWithShadowsOn) {
    const std::string name = GetParam();
    const Frame f = frame_zero(name);
    ASSERT_FALSE(f.grounds.empty()) << "no ground to throw shadows on";
    render::RenderOptions o{kWidth, kHeight};
    o.samples = 1; // each pixel is one point of one surface
    // Ambient occlusion darkens the ground near bodies with shadows on or off; off here, so
    // that ground a body does not cover is drawn alike with and without the body.
    o.ambient_occlusion = false;
    render::RenderOptions no_shadows = o;
    no_shadows.shadows = false;
    Renderers r{render::Renderer(o), render::Renderer(no_shadows), {}};
    render::SceneView ground_only = f.view;
    std::erase_if(ground_only.instances,
                  [](const render::Instance& in) { return in.mesh != render::MeshKind::Plane; });
    r.plain.draw(ground_only, r.ground_off);
    const std::vector<GroundPixel> pixels = ground_pixels(f);

    // The whole frame first; the bodies it cannot judge then in groups whose shadows lie apart.
    std::vector<std::size_t> all(f.casters.size()), dynamic, again;
    for (std::size_t i = 0; i < all.size(); ++i) {
        all[i] = i;
        if (f.dynamic[i]) dynamic.push_back(i);
    }
    std::string file = name; // lessons/top -> lessons_top
    std::replace(file.begin(), file.end(), '/', '_');
    const std::string saved = std::string(TUMBLE_TEST_ARTIFACTS) + "/body_shadows_" + file;
    const std::vector<int> in_view = shadow_pixels_in_view(f, pixels);
    std::vector<Tally> tally = judge(f, all, pixels, r, saved);
    for (std::size_t i : dynamic)
        if (tally[i].pixels < kMinPixels && in_view[i] >= kMinPixels) again.push_back(i);
    const std::vector<std::vector<std::size_t>> groups = apart(f, again);
    for (const std::vector<std::size_t>& g : groups) {
        const std::vector<Tally> t = judge(f, g, pixels, r);
        for (std::size_t a = 0; a < g.size(); ++a) tally[g[a]] = t[a];
    }
    std::size_t alone = 0;
    for (std::size_t i : again)
        if (tally[i].pixels < kMinPixels) tally[i] = judge(f, {i}, pixels, r)[0], ++alone;

    int judged = 0, shadows_in_view = 0;
    double least = 1.0;
    for (std::size_t i : dynamic) {
        const std::string body = "body " + std::to_string(f.body[i]) + " \"" +
                                 f.scene.looks[std::size_t(f.body[i])].name + "\"";
        shadows_in_view += in_view[i] >= kMinPixels;
        if (in_view[i] >= kMinPixels) {
            EXPECT_GE(tally[i].pixels, kMinPixels)
                << body << ": " << in_view[i] << " ground pixels in view lie in its shadow, but "
                << tally[i].pixels << " could be judged even drawn alone";
        }
        if (tally[i].pixels < kMinPixels) continue; // its shadow is not in the picture
        ++judged;
        const double darkening = tally[i].darkening();
        least = std::min(least, darkening);
        EXPECT_GE(darkening, kMinDarkening)
            << body << " casts no shadow: the ground it shades is " << darkening
            << " darker with shadows on, over " << tally[i].pixels << " pixels";
        if (dynamic.size() <= 30 || darkening < kMinDarkening)
            std::printf("[shadow] %s, %s: darkening %.3f over %d pixels\n", name.c_str(),
                        body.c_str(), darkening, tally[i].pixels);
    }
    std::printf("[shadow] %s: %d of %zu dynamic bodies judged, of %d whose shadow falls in view "
                "(%zu drawn again in %zu groups apart, %zu of them alone); the others' shadows "
                "are out of the picture or behind the body\n",
                name.c_str(), judged, dynamic.size(), shadows_in_view, again.size(), groups.size(),
                alone);
    TUMBLE_MEASURED(least, kMinDarkening);
    EXPECT_GE(judged, shadows_in_view);
    EXPECT_GE(judged, 1) << "no body's shadow could be judged in this scene";
}

INSTANTIATE_TEST_SUITE_P(BuiltInScenes, EveryBodyCastsAShadow,
                         ::testing::ValuesIn(builtin_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param; // lessons/top -> lessons_top
                             std::replace(name.begin(), name.end(), '/', '_');
                             return name;
                         });

} // namespace
} // namespace tumble::app
