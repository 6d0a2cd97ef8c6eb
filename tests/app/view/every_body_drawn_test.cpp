// Every body of every built-in scene is drawn where its pose projects (issue 26): at 320x180, the
// size of the project's image goldens, at frame 0 and at t = 0.5 s.
//
// Where a body must show is worked out here, not read from the renderer: a pinhole camera from
// the scene's camera (position, target, up, vertical field of view) casts a ray through each
// pixel, and the ray meets each body's shape at its pose (light_rays.h: spheres, boxes, capsules,
// the drawn triangles of a mesh) and the ground squares. A body's own pixels are those whose ray
// and their 8 neighbours' rays meet it first: clear of its outline, which anti-aliasing and the
// renderer's polygons blur.
//
// What the renderer drew there is read by recolouring (the instances build_view tags with the
// body's index): bodies are put in groups whose outlines on screen (projected bounding spheres)
// do not overlap, group g gets the code g + 1, and the frame is drawn once as is and once per bit
// of the codes with the bodies whose code has that bit drawn in a far colour. Colour changes
// nothing else (lighting, shadows and occlusion do not depend on it), so a pixel showing body b
// changes in exactly the drawings of b's code (recoloured bodies are drawn matte, so that no
// white highlight stays). Each own pixel must read its body's code (95% of them; measured: all,
// in every scene): a body skipped, drawn elsewhere or with another's pose reads another code
// there, or none. And every pixel that changed must lie in the outline of a
// body whose code shares a bit with it: a body drawn away from its pose fails that.
//
// Bodies hidden behind others (the sphere-rain block) are judged again drawn alone with the
// ground, in groups apart. Every body whose centre projects into the picture must be judged in
// one of the two.
#include "app/run/auto_camera.h"
#include "app/run/render_frames.h"
#include "app/run/simulation.h"
#include "app/scene/scene.h"
#include "app/view/view_builder.h"
#include "render/png_io.h"
#include "render/renderer.h"

#include "light_rays.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace tumble::app {
namespace {

using render::test::BodyShape;

constexpr int kWidth = 320, kHeight = 180;
constexpr double kLaterTime = 0.5; // s: the second frame judged, bodies moved and turned
constexpr int kMinChange = 2;      // a pixel changed: some channel moved by more than this
constexpr double kMinRight = 0.95; // of a body's own pixels that must show it, per drawing

// The scene's camera as a pinhole: the ray through a point of the picture (pixels from the top
// left corner), in double precision from the camera's own fields.
struct Pinhole {
    glm::dvec3 eye, forward, right, up;
    double tan_y = 0.0, tan_x = 0.0, near = 0.0;
    explicit Pinhole(const render::Camera& c)
        : eye(c.position), forward(glm::normalize(glm::dvec3(c.target) - eye)),
          right(glm::normalize(glm::cross(forward, glm::dvec3(c.up)))),
          up(glm::cross(right, forward)),
          tan_y(std::tan(0.5 * double(c.fov_y_deg) * 3.14159265358979323846 / 180.0)),
          tan_x(tan_y * kWidth / kHeight), near(c.z_near) {}
    glm::dvec3 ray(double px, double py) const {
        const double sx = (2.0 * px / kWidth - 1.0) * tan_x;
        const double sy = (1.0 - 2.0 * py / kHeight) * tan_y;
        return glm::normalize(forward + sx * right + sy * up);
    }
    // Pixel coordinates of a camera-frame point (x right, y up, z forward), z > 0.
    double px(double x, double z) const { return (x / (z * tan_x) + 1.0) * 0.5 * kWidth; }
    double py(double y, double z) const { return (1.0 - y / (z * tan_y)) * 0.5 * kHeight; }
};

struct Box2 {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1; // inclusive pixel range; empty when x1 < x0
    bool empty() const { return x1 < x0 || y1 < y0; }
    bool overlaps(const Box2& o) const {
        return !empty() && !o.empty() && x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1;
    }
};

// The pixels a sphere of radius r about c can cover, from the extremes of x/z and y/z over it;
// the whole picture when it reaches the near plane.
Box2 footprint(const Pinhole& cam, glm::dvec3 c, double r) {
    const glm::dvec3 d = c - cam.eye;
    const double x = glm::dot(d, cam.right), y = glm::dot(d, cam.up), z = glm::dot(d, cam.forward);
    if (z + r <= cam.near) return {};
    if (z - r <= cam.near) return {0, 0, kWidth - 1, kHeight - 1};
    const double xs[4] = {cam.px(x - r, z - r), cam.px(x - r, z + r), cam.px(x + r, z - r),
                          cam.px(x + r, z + r)};
    const double ys[4] = {cam.py(y + r, z - r), cam.py(y + r, z + r), cam.py(y - r, z - r),
                          cam.py(y - r, z + r)};
    // 2 px more all round: own_pixels() casts rays up to 1.05 px from a pixel's centre.
    Box2 b{int(std::floor(*std::min_element(xs, xs + 4))) - 2,
           int(std::floor(*std::min_element(ys, ys + 4))) - 2,
           int(std::ceil(*std::max_element(xs, xs + 4))) + 2,
           int(std::ceil(*std::max_element(ys, ys + 4))) + 2};
    b.x0 = std::max(b.x0, 0), b.y0 = std::max(b.y0, 0);
    b.x1 = std::min(b.x1, kWidth - 1), b.y1 = std::min(b.y1, kHeight - 1);
    return b;
}

struct Ground {
    glm::dvec3 point, normal, axis_x, axis_y;
    double half_extent;
};

// One frame of a scene: what is drawn, and every body but the grounds as a shape.
struct Frame {
    Scene scene;
    render::SceneView view;
    std::vector<BodyShape> bodies; // the scene's bodies but the planes
    std::vector<int> index;        // bodies[k] is the scene's body index[k]
    std::vector<int> caster;       // per scene body: its index into bodies, -1 for a plane
    std::vector<Box2> outline;     // per body, on screen
    std::vector<Ground> grounds;
};

Frame frame_at(const std::string& name, double seconds) {
    Frame f;
    f.scene = load_scene_argument(name);
    f.scene.render.width = kWidth, f.scene.render.height = kHeight;
    const Timeline tl = make_timeline(f.scene.world.dt, f.scene.duration, f.scene.render.fps);
    frame_automatically(f.scene, tl);
    Simulation sim = make_simulation(f.scene, tl.h);
    const std::int64_t frame =
        std::min<std::int64_t>(std::llround(seconds * tl.fps), tl.frames - 1);
    for (std::int64_t s = 0; s < frame * tl.steps_per_frame; ++s) sim.step();
    build_view(f.scene, sim.model, sim.state, f.view);
    // Bodies only: no overlay text, charts, trails, arrows or axis rods in front of them.
    f.view.overlay.clear(), f.view.canvas.clear(), f.view.lines.clear();
    std::erase_if(f.view.instances, [](const render::Instance& in) { return in.body < 0; });
    for (render::Instance& in : f.view.instances) in.axes = false; // rods in their own colours
    const Pinhole cam(f.view.camera);
    f.caster.assign(std::size_t(sim.model.body_count()), -1);
    for (int i = 0; i < sim.model.body_count(); ++i) {
        const physics::Shape& s = sim.model.shape[std::size_t(i)];
        const BodyLook& look = f.scene.looks[std::size_t(i)];
        const BodyShape b = render::test::body_shape(
            s, physics::body_pose(sim.model, sim.state, i),
            s.kind == physics::ShapeKind::Mesh ? f.scene.meshes[look.mesh_id].get() : nullptr);
        if (s.kind == physics::ShapeKind::Plane) {
            f.grounds.push_back(
                {b.position, b.rotation[2], b.rotation[0], b.rotation[1], 0.5 * look.plane_extent});
            continue;
        }
        f.caster[std::size_t(i)] = int(f.bodies.size());
        f.bodies.push_back(b);
        f.index.push_back(i);
        f.outline.push_back(footprint(cam, b.position, b.bound));
    }
    return f;
}

// Which of `drawn` (indices into f.bodies) the rays through points `at` (offsets from each pixel's
// centre, pixels) meet first, judged over the bodies whose outlines hold the pixel (-1: a ground,
// the sky): hit[at.size() * pixel + k].
template <std::size_t N>
std::vector<int> first_met(const Frame& f, const std::vector<std::size_t>& drawn,
                           const std::array<std::array<double, 2>, N>& at) {
    const Pinhole cam(f.view.camera);
    std::vector<std::vector<std::size_t>> candidates(std::size_t(kWidth * kHeight));
    for (std::size_t b : drawn)
        for (int y = f.outline[b].y0; y <= f.outline[b].y1; ++y)
            for (int x = f.outline[b].x0; x <= f.outline[b].x1; ++x)
                candidates[std::size_t(y * kWidth + x)].push_back(b);
    std::vector<int> hit(N * std::size_t(kWidth * kHeight), -1);
    for (std::size_t i = 0; i < N * std::size_t(kWidth * kHeight); ++i) {
        const std::size_t pixel = i / N;
        const int x = int(pixel) % kWidth, y = int(pixel) / kWidth;
        const std::vector<std::size_t>& c = candidates[pixel];
        if (c.empty()) continue;
        const glm::dvec3 u = cam.ray(x + 0.5 + at[i % N][0], y + 0.5 + at[i % N][1]);
        {
            double nearest = render::test::kMiss;
            for (const Ground& g : f.grounds) {
                const double t = glm::dot(g.normal, g.point - cam.eye) / glm::dot(g.normal, u);
                const glm::dvec3 p = cam.eye + t * u - g.point;
                if (t > 0.0 && std::max(std::abs(glm::dot(p, g.axis_x)),
                                        std::abs(glm::dot(p, g.axis_y))) < g.half_extent)
                    nearest = std::min(nearest, t);
            }
            for (std::size_t b : c) {
                const double t = render::test::ray_entry(f.bodies[b], cam.eye, u);
                if (t < nearest) nearest = t, hit[i] = int(b);
            }
        }
    }
    return hit;
}

// A body's own pixels: those whose centre's ray and the rays through 8 points kClear around it
// all meet that body first. Its outline then lies about kClear from the centre all round (its
// picture is convex where nothing covers it), clear of the multisamples (within 0.4 px of the
// centre) and of the renderer's polygons, whose outline may lie up to 0.6 px inside the true
// one (render/draw_list.h, kCameraError). own[pixel] is that body, or -1.
std::vector<int> own_pixels(const Frame& f, const std::vector<std::size_t>& drawn) {
    constexpr double kClear = 1.05;
    std::array<std::array<double, 2>, 9> at{{{0.0, 0.0}}};
    for (int k = 0; k < 8; ++k) {
        const double a = k * 3.14159265358979323846 / 4.0;
        at[std::size_t(k + 1)] = {kClear * std::cos(a), kClear * std::sin(a)};
    }
    const std::vector<int> hit = first_met(f, drawn, at);
    std::vector<int> own(std::size_t(kWidth * kHeight), -1);
    for (std::size_t p = 0; p < own.size(); ++p) {
        const int b = hit[9 * p];
        bool inside = b >= 0;
        for (std::size_t k = 1; k < 9 && inside; ++k) inside = hit[9 * p + k] == b;
        if (inside) own[p] = b;
    }
    return own;
}

// `bodies` split into groups whose outlines do not overlap (greedy, in order).
std::vector<std::vector<std::size_t>> apart(const Frame& f,
                                            const std::vector<std::size_t>& bodies) {
    std::vector<std::vector<std::size_t>> groups;
    for (std::size_t b : bodies) {
        const auto fits = [&](const std::vector<std::size_t>& g) {
            return std::none_of(g.begin(), g.end(),
                                [&](std::size_t o) { return f.outline[b].overlaps(f.outline[o]); });
        };
        const auto g = std::find_if(groups.begin(), groups.end(), fits);
        if (g != groups.end())
            g->push_back(b);
        else
            groups.push_back({b});
    }
    return groups;
}

// A colour far from `c` in every channel: what a recoloured body is drawn in (matte).
glm::vec3 far_colour(glm::vec3 c) {
    return {c.r < 0.5f ? 1.0f : 0.0f, c.g < 0.5f ? 1.0f : 0.0f, c.b < 0.5f ? 1.0f : 0.0f};
}

// The view with the grounds and the bodies `drawn` (per index into f.bodies), those with
// recolour[b] drawn in a far colour.
render::SceneView view_of(const Frame& f, const std::vector<bool>& drawn,
                          const std::vector<bool>& recolour) {
    render::SceneView v = f.view;
    std::erase_if(v.instances, [&](const render::Instance& in) {
        const int b = f.caster[std::size_t(in.body)];
        return b >= 0 && !drawn[std::size_t(b)];
    });
    for (render::Instance& in : v.instances)
        if (const int b = f.caster[std::size_t(in.body)]; b >= 0 && recolour[std::size_t(b)]) {
            in.color = far_colour(in.color);
            in.material = {1.0f, 0.0f, 0.0f}; // no highlight: a white one would not change
        }
    return v;
}

bool changed(const render::Image& a, const render::Image& b, std::size_t pixel) {
    for (std::size_t c = 0; c < 3; ++c)
        if (std::abs(int(a.rgb[3 * pixel + c]) - int(b.rgb[3 * pixel + c])) > kMinChange)
            return true;
    return false;
}

struct Tally {
    int own = 0, right = 0; // own pixels, and of those the ones that changed as the body's code
    int centre = -1;        // drawn alone: whether the pixel of its centre read its code (-1: off)
    double fraction() const { return own ? double(right) / own : 0.0; }
};

// The pixel the body's centre projects to, or -1 outside the picture (or behind the camera).
long centre_pixel(const Frame& f, std::size_t b) {
    const Pinhole cam(f.view.camera);
    const glm::dvec3 d = f.bodies[b].position - cam.eye;
    const double z = glm::dot(d, cam.forward);
    if (z <= cam.near) return -1;
    const double x = cam.px(glm::dot(d, cam.right), z), y = cam.py(glm::dot(d, cam.up), z);
    if (x < 0 || x >= kWidth || y < 0 || y >= kHeight) return -1;
    return long(y) * kWidth + long(x);
}

// Draws the bodies `drawn`, then again once per bit of the groups' codes (group g has code
// g + 1) with the bodies whose code has that bit recoloured. A pixel showing body b changes in
// exactly the drawings of b's code, so each own pixel of a group's body must read its code: a body
// missing, drawn elsewhere or with another's pose reads another code (or none) there. Tallies
// those pixels, and returns the changed pixels outside the outline of every body whose code
// shares a bit with what the pixel read (a body drawn away from its pose).
int judge(const Frame& f, render::Renderer& renderer, const std::vector<bool>& drawn,
          const std::vector<std::vector<std::size_t>>& groups, std::vector<Tally>& tally) {
    std::vector<std::size_t> list;
    for (std::size_t b = 0; b < drawn.size(); ++b)
        if (drawn[b]) list.push_back(b);
    const std::vector<int> own = own_pixels(f, list);
    std::vector<unsigned> code(drawn.size(), 0);
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (std::size_t b : groups[g]) code[b] = unsigned(g + 1);
    render::Image base, coloured;
    renderer.draw(view_of(f, drawn, std::vector<bool>(drawn.size(), false)), base);
    std::vector<unsigned> read(own.size(), 0);
    for (unsigned bit = 1; bit <= groups.size(); bit <<= 1) {
        std::vector<bool> recolour(drawn.size());
        for (std::size_t b = 0; b < drawn.size(); ++b) recolour[b] = (code[b] & bit) != 0;
        renderer.draw(view_of(f, drawn, recolour), coloured);
        for (std::size_t p = 0; p < own.size(); ++p)
            if (changed(base, coloured, p)) read[p] |= bit;
    }
    for (std::size_t b : list) // too small for own pixels: the pixel of its centre, at least
        if (const long p = centre_pixel(f, b); p >= 0 && code[b] != 0)
            tally[b].centre = (read[std::size_t(p)] & code[b]) == code[b];
    int stray = 0;
    for (std::size_t p = 0; p < own.size(); ++p) {
        if (own[p] >= 0 && code[std::size_t(own[p])] != 0) {
            Tally& t = tally[std::size_t(own[p])];
            ++t.own;
            t.right += read[p] == code[std::size_t(own[p])];
        }
        if (read[p] == 0) continue;
        const int x = int(p) % kWidth, y = int(p) / kWidth;
        bool outlined = false;
        for (std::size_t b : list)
            outlined =
                outlined || ((code[b] & read[p]) != 0 && x >= f.outline[b].x0 &&
                             x <= f.outline[b].x1 && y >= f.outline[b].y0 && y <= f.outline[b].y1);
        stray += !outlined;
    }
    return stray;
}

void expect_every_body_drawn(const std::string& name, double seconds) {
    const Frame f = frame_at(name, seconds);
    render::Renderer renderer(render_options(f.scene.render));
    const std::size_t n = f.bodies.size();
    std::vector<std::size_t> everyone(n);
    for (std::size_t b = 0; b < n; ++b) everyone[b] = b;

    // The whole frame, in groups apart on screen; then the hidden bodies, each group drawn alone
    // with the ground.
    std::vector<Tally> whole(n), alone(n);
    const std::vector<std::vector<std::size_t>> all_groups = apart(f, everyone);
    int stray = judge(f, renderer, std::vector<bool>(n, true), all_groups, whole);
    std::vector<std::size_t> hidden;
    for (std::size_t b = 0; b < n; ++b)
        if (whole[b].own == 0) hidden.push_back(b);
    const std::vector<std::vector<std::size_t>> groups = apart(f, hidden);
    for (const std::vector<std::size_t>& g : groups) {
        std::vector<bool> drawn(n, false);
        for (std::size_t b : g) drawn[b] = true;
        stray += judge(f, renderer, drawn, {g}, alone);
    }

    int judged = 0, in_view = 0, by_centre = 0;
    double least = 1.0;
    for (std::size_t b = 0; b < n; ++b) {
        const long centre = centre_pixel(f, b);
        in_view += centre >= 0;
        const std::string body = "body " + std::to_string(f.index[b]) + " \"" +
                                 f.scene.looks[std::size_t(f.index[b])].name + "\"";
        for (const Tally* t : {&whole[b], &alone[b]}) {
            if (t->own == 0) continue;
            least = std::min(least, t->fraction());
            EXPECT_GE(t->fraction(), kMinRight)
                << body << " is not drawn where its pose projects: " << t->right << " of its "
                << t->own << " pixels show it (" << (t == &whole[b] ? "whole frame" : "drawn alone")
                << ")";
        }
        const bool own = whole[b].own > 0 || alone[b].own > 0;
        if (!own && alone[b].centre >= 0) { // too small on screen for own pixels
            ++by_centre;
            EXPECT_EQ(alone[b].centre, 1)
                << body << ", drawn alone, does not show at the pixel (" << centre % kWidth << ", "
                << centre / kWidth << ") its centre projects to";
        }
        judged += own || alone[b].centre >= 0;
        if (centre >= 0) {
            EXPECT_TRUE(own || alone[b].centre >= 0)
                << body << ": its centre projects to (" << centre % kWidth << ", "
                << centre / kWidth << ") but it could not be judged";
        }
    }
    std::printf("[drawn] %s at t = %g s: %d of %zu bodies judged, %d of them by the pixel of their "
                "centre alone (%zu groups in the whole frame; %zu hidden ones drawn alone in %zu "
                "groups); %d with their centre in the picture\n",
                name.c_str(), seconds, judged, n, by_centre, all_groups.size(), hidden.size(),
                groups.size(), in_view);
    TUMBLE_MEASURED(least, kMinRight);
    TUMBLE_MEASURED(stray, 0);
    EXPECT_EQ(stray, 0) << "pixels changed by recolouring outside the outline of every body so "
                           "coloured: a body drawn away from its pose";
    EXPECT_GE(judged, 1);
}

class EveryBodyIsDrawn : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryBodyIsDrawn, WhereItsPoseProjects) {
    expect_every_body_drawn(GetParam(), 0.0);
    expect_every_body_drawn(GetParam(), kLaterTime);
}

INSTANTIATE_TEST_SUITE_P(BuiltInScenes, EveryBodyIsDrawn,
                         ::testing::ValuesIn(builtin_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param; // lessons/top -> lessons_top
                             std::replace(name.begin(), name.end(), '/', '_');
                             return name;
                         });

} // namespace
} // namespace tumble::app
