// Issue 30, item 5: the lessons' pictures show their point. Lesson 1: at t = 4.5 s the spinning
// plate's L arrow is seen beside its w arrow (not hidden in it), both tips in the frame of the
// lesson's camera, in a colour apart from the plate's, its axes' and its trail's. Lesson 5: the
// trail of the top's axis hangs from the axis, drawn out to the trail's newest point, without
// --axes. Measured in pixels and in the world from what the physics says L is, not from the arrows'
// own code.
#include "app/cli/render_setup.h"
#include "app/run/frame_source.h"
#include "app/run/render_frames.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "physics/diagnostics.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tumble::app {
namespace {

struct Frame {
    Scene scene;
    std::unique_ptr<Simulation> sim;
    render::SceneView view;
};

// Frame `k` of `cmd`'s run, at 640x360.
Frame frame_of(RenderCommand cmd, std::int64_t k) {
    cmd.common.quiet = true;
    cmd.width = 640, cmd.height = 360;
    Frame f;
    f.scene = load_for_command(cmd.common);
    apply_render_overrides(cmd, f.scene);
    const Timeline tl = make_timeline(f.scene.world.dt, f.scene.duration, f.scene.render.fps);
    f.sim = std::make_unique<Simulation>(make_simulation(f.scene, tl.h));
    FrameSource source(f.scene, tl, *f.sim, k, k);
    EXPECT_TRUE(source.next(f.view));
    return f;
}

int body_named(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.looks.size(); ++i)
        if (scene.looks[i].name == name) return int(i);
    ADD_FAILURE() << "no body " << name;
    return 0;
}

glm::vec3 axis_of(const render::Instance& in) {
    return glm::normalize(glm::vec3(in.transform[2]));
}

long long differing(const render::Image& a, const render::Image& b) {
    long long n = 0;
    for (std::size_t p = 0; p < a.rgb.size(); p += 3)
        n += !std::equal(a.rgb.begin() + long(p), a.rgb.begin() + long(p) + 3,
                         b.rgb.begin() + long(p));
    return n;
}

// Hue in degrees of an sRGB colour.
double hue(glm::vec3 c) {
    const float mx = std::max({c.r, c.g, c.b}), mn = std::min({c.r, c.g, c.b});
    if (mx - mn < 1e-6f) return 0.0;
    double h = mx == c.r   ? (c.g - c.b) / (mx - mn)
               : mx == c.g ? 2 + (c.b - c.r) / (mx - mn)
                           : 4 + (c.r - c.g) / (mx - mn);
    return std::fmod(60.0 * h + 360.0, 360.0);
}
double hue_apart(glm::vec3 a, glm::vec3 b) {
    const double d = std::abs(hue(a) - hue(b));
    return std::min(d, 360.0 - d);
}

TEST(LessonPictures, LessonOnesLArrowIsSeenBesideW) {
    RenderCommand cmd;
    cmd.common.scene = "lessons/wobbling_plate";
    cmd.vectors = cmd.axes = true;
    cmd.trail_axis = "z";
    const Frame f = frame_of(cmd, 270); // t = 4.5 s at 60 fps
    const int plate = body_named(f.scene, "plate");
    const physics::Vec3 L = physics::spin_angular_momentum(f.sim->model, f.sim->state, plate);
    const glm::vec3 l = glm::normalize(glm::vec3(float(L.x()), float(L.y()), float(L.z())));
    // The L arrow: the shapes that are not the body's and point along L.
    render::SceneView without_l = f.view, only_l = f.view, empty = f.view;
    without_l.instances.clear(), only_l.instances.clear(), empty.instances.clear();
    for (auto* v : {&only_l, &empty}) v->lines.clear(), v->canvas.clear(), v->overlay.clear();
    glm::vec3 l_colour(0.0f), w_colour(0.0f);
    for (const render::Instance& in : f.view.instances) {
        const bool arrow = in.body < 0 && in.mesh != render::MeshKind::Plane;
        const bool along_l = arrow && glm::dot(axis_of(in), l) > 0.99999f;
        if (along_l)
            l_colour = in.color;
        else if (arrow && in.mesh == render::MeshKind::Custom)
            w_colour = in.color; // w's head
        (along_l ? only_l : without_l).instances.push_back(in);
    }
    ASSERT_GT(only_l.instances.size(), 0u) << "no arrow along L";
    // Both arrows' tips (each head's apex, z = 1 of the unit cone) inside the frame: an arrow
    // whose head is cut off by the frame's edge does not say where it points.
    const glm::mat4 vp = render::projection_matrix(f.view.camera, 640.0f / 360.0f) *
                         render::view_matrix(f.view.camera);
    int heads = 0;
    for (const render::Instance& in : f.view.instances) {
        if (in.body >= 0 || in.mesh != render::MeshKind::Custom) continue;
        const glm::vec4 c = vp * (in.transform * glm::vec4(0, 0, 1, 1));
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        EXPECT_TRUE(c.w > 0 && std::abs(ndc.x) < 0.98f && std::abs(ndc.y) < 0.98f)
            << "an arrow's tip at " << ndc.x << ", " << ndc.y << " (NDC) is not in the frame";
        ++heads;
    }
    EXPECT_EQ(heads, 2); // w's and L's
    render::RenderOptions o;
    o.width = 640, o.height = 360;
    render::Renderer renderer(o);
    render::Image all, no_l, alone, none;
    renderer.draw(f.view, all);
    renderer.draw(without_l, no_l);
    renderer.draw(only_l, alone);
    renderer.draw(empty, none);
    const double seen = double(differing(all, no_l)) / double(differing(alone, none));
    TUMBLE_MEASURED(seen, 0.6);
    EXPECT_GT(seen, 0.6);
    // Its colour is apart from w's, the plate's, the axes' (red, green, blue) and the trail's.
    std::vector<glm::vec3> others = {w_colour,
                                     f.scene.looks[std::size_t(plate)].color,
                                     {0.86f, 0.16f, 0.12f},
                                     {0.20f, 0.70f, 0.22f},
                                     {0.16f, 0.36f, 0.90f}};
    for (const glm::vec4& c : f.view.lines.colors) others.push_back(glm::vec3(c));
    double nearest = 360.0;
    for (const glm::vec3& c : others) nearest = std::min(nearest, hue_apart(l_colour, c));
    TUMBLE_MEASURED(nearest, 40.0);
    EXPECT_GT(nearest, 40.0);
}

TEST(LessonPictures, LessonFivesTrailHangsFromTheAxis) {
    RenderCommand cmd;
    cmd.common.scene = "lessons/top_precession";
    cmd.trail_axis = "z";
    const Frame f = frame_of(cmd, 120);
    // The tip's trail: the strip whose newest point is farthest from the top's centre.
    const int top = body_named(f.scene, "top");
    const physics::Vec3 c = f.sim->state.x[std::size_t(top)];
    const glm::vec3 centre(float(c.x()), float(c.y()), float(c.z()));
    glm::vec3 tip = centre;
    for (const auto& s : f.view.lines.strips) {
        const glm::vec3 newest = f.view.lines.points[s.first + s.count - 1];
        if (glm::length(newest - centre) > glm::length(tip - centre)) tip = newest;
    }
    ASSERT_GT(glm::length(tip - centre), 0.01f) << "no axis trail";
    // Some drawn rod runs from the centre out to it.
    double best = 1e9;
    for (const render::Instance& in : f.view.instances) {
        if (in.mesh != render::MeshKind::Cylinder) continue;
        const glm::vec3 a(in.transform * glm::vec4(0, 0, -1, 1)),
            b(in.transform * glm::vec4(0, 0, 1, 1));
        best = std::min(best, double(std::max(glm::length(a - centre), glm::length(b - tip))));
    }
    TUMBLE_MEASURED(best, 1e-4);
    EXPECT_LT(best, 1e-4);
}

} // namespace
} // namespace tumble::app
