// Issue 30, item 3: Poinsot's construction that reads. The camera looks down on the invariable
// plane at an angle with the construction in frame (judged against L and T computed here from
// the state, not from the construction's code); the ellipsoid is drawn as a surface (most pixels
// inside its outline change when it is drawn, where a wireframe changed few); the curves are named
// in the frame; and a body that may feel a torque, for which the construction does not hold, is
// warned about on the command line and in the frame.
#include "app/cli/render_setup.h"
#include "app/run/auto_camera.h"
#include "app/run/frame_source.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "physics/diagnostics.h"
#include "render/camera.h"
#include "render/png_io.h"
#include "support/cli_runner.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tumble::app {
namespace {

using physics::Vec3;

// Lesson 4 with its construction, as `render lessons/intermediate_axis --poinsot book` sets it up
// at `width` x `height`, the camera framed.
Scene lesson4(int width, int height, const std::string& camera = "") {
    RenderCommand cmd;
    cmd.common.scene = "lessons/intermediate_axis";
    cmd.common.quiet = true;
    cmd.poinsot = "book";
    cmd.width = width, cmd.height = height;
    if (!camera.empty()) cmd.camera = camera;
    Scene scene = load_for_command(cmd.common);
    apply_render_overrides(cmd, scene);
    frame_automatically(scene, make_timeline(scene.world.dt, scene.duration, scene.render.fps));
    return scene;
}

// The point p on the screen of `camera`, in [-1, 1]^2 when inside the frame.
glm::vec2 ndc(const render::Camera& camera, float aspect, const Vec3& p) {
    const glm::vec4 c = render::projection_matrix(camera, aspect) * render::view_matrix(camera) *
                        glm::vec4(float(p.x()), float(p.y()), float(p.z()), 1.0f);
    return glm::vec2(c) / c.w;
}

TEST(Poinsot, TheCameraLooksDownOnTheInvariablePlaneWithTheConstructionInFrame) {
    for (const auto& [w, h] : {std::pair{1280, 720}, {320, 180}}) {
        const Scene scene = lesson4(w, h);
        const Simulation sim = make_simulation(scene, scene.world.dt);
        const int book = scene.render.poinsot.index;
        // Independently: L = I_w w and 2T = w . L from the state.
        const Vec3 L = physics::spin_angular_momentum(sim.model, sim.state, book);
        const Vec3 wv = sim.state.w[std::size_t(book)];
        const double two_t = wv.dot(L);
        const Vec3 n = L.normalized(), centre = sim.state.x[std::size_t(book)];
        const render::Camera& cam = scene.render.camera.base;
        const Vec3 eye(cam.position.x, cam.position.y, cam.position.z);
        // The camera is on the ellipsoid's side of the plane (the centre's), looking down on it
        // at 20 to 60 degrees: the plane is neither edge-on nor seen square.
        const Vec3 to_eye = (eye - centre).normalized();
        const double elevation = std::asin(-to_eye.dot(n)) * 180.0 / std::numbers::pi;
        TUMBLE_MEASURED(elevation, 20.0);
        EXPECT_GT(elevation, 20.0) << w << "x" << h;
        EXPECT_LT(elevation, 60.0) << w << "x" << h;
        // The ellipsoid's ends (semi-axes sqrt(2T / I_i), 1.5 body sizes for the longest) and the
        // point of contact are in frame.
        const Vec3 I = sim.model.inertia[std::size_t(book)];
        const double size = 1.7 * std::sqrt(I.maxCoeff() / sim.model.mass[std::size_t(book)]);
        const Vec3 semi = (two_t / I.array()).sqrt().matrix();
        const double scale = 1.5 * size / semi.maxCoeff();
        const float aspect = float(w) / float(h);
        std::vector<Vec3> points{centre + scale * wv};
        for (int k = 0; k < 3; ++k)
            for (double sign : {-1.0, 1.0})
                points.push_back(centre + sign * scale * semi[k] *
                                              (sim.state.q[std::size_t(book)] * Vec3::Unit(k)));
        for (const Vec3& p : points) {
            const glm::vec2 s = ndc(cam, aspect, p);
            EXPECT_LT(std::max(std::abs(s.x), std::abs(s.y)), 1.0f) << w << "x" << h;
        }
    }
}

TEST(Poinsot, TheCurvesAreNamedInTheFrame) {
    const Scene scene = lesson4(640, 360);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    Simulation sim = make_simulation(scene, tl.h);
    FrameSource frames(scene, tl, sim, 60, 60);
    render::SceneView view;
    ASSERT_TRUE(frames.next(view));
    std::vector<std::string> labels;
    for (const auto& l : view.canvas.labels) labels.push_back(l.text);
    for (const char* name : {"polhode", "herpolhode", "ellipsoid", "invariable plane"})
        EXPECT_TRUE(std::any_of(labels.begin(), labels.end(), [&](const std::string& t) {
            return t.find(name) != t.npos;
        })) << name;
    // Torque-free: nothing in the frame says otherwise.
    for (const std::string& t : labels) EXPECT_EQ(t.find("torque"), std::string::npos) << t;
}

// The pixels inside the convex outline of `points` on the screen.
std::vector<bool> inside_outline(const std::vector<glm::vec2>& points, int w, int h) {
    std::vector<glm::vec2> p = points; // Andrew's monotone chain
    std::sort(p.begin(), p.end(),
              [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::vec2> hull;
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t start = hull.size();
        for (const glm::vec2& q : p) {
            while (hull.size() >= start + 2 && cross(hull[hull.size() - 2], hull.back(), q) <= 0)
                hull.pop_back();
            hull.push_back(q);
        }
        hull.pop_back();
        std::reverse(p.begin(), p.end());
    }
    std::vector<bool> in(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec2 c(float(x) + 0.5f, float(y) + 0.5f);
            bool all = true;
            for (std::size_t i = 0; i < hull.size() && all; ++i)
                all = cross(hull[i], hull[(i + 1) % hull.size()], c) > 0.0f;
            in[std::size_t(y) * std::size_t(w) + std::size_t(x)] = all;
        }
    return in;
}

TEST(PoinsotCli, TheEllipsoidIsDrawnAsASurface) {
    const auto dir = test::scratch_dir();
    const int w = 320, h = 180;
    const std::string camera = "0.9,-0.9,1.6:0,0,1:40";
    const std::string still = "render lessons/intermediate_axis --time 2 --width 320 --height 180 "
                              "-q --camera " +
                              camera;
    ASSERT_EQ(test::run_tumble(dir, still + " -o plain.png").exit_code, 0);
    const test::CliResult r = test::run_tumble(dir, still + " --poinsot book -o poinsot.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const render::Image a = render::read_png(dir / "plain.png"),
                        b = render::read_png(dir / "poinsot.png");
    // The ellipsoid's outline on the screen, from the state at t = 2 s stepped here.
    const Scene scene = lesson4(w, h, camera);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    Simulation sim = make_simulation(scene, tl.h);
    for (int k = 0; k < 120 * tl.steps_per_frame; ++k) sim.step();
    const std::size_t book = std::size_t(scene.render.poinsot.index);
    const Vec3 I = sim.model.inertia[book], wv = sim.state.w[book];
    const Vec3 wb = sim.state.q[book].conjugate() * wv;
    const double two_t = wb.dot(I.cwiseProduct(wb));
    const Vec3 semi = (two_t / I.array()).sqrt().matrix();
    const Scene at_start = lesson4(w, h, camera);
    const Simulation start = make_simulation(at_start, tl.h);
    const Vec3 L0 = physics::spin_angular_momentum(start.model, start.state, int(book));
    const double scale = 1.5 * 1.7 * std::sqrt(I.maxCoeff() / sim.model.mass[book]) /
                         (L0.dot(start.state.w[book]) / I.array()).sqrt().maxCoeff();
    std::vector<glm::vec2> outline;
    for (int i = 0; i < 24; ++i)
        for (int j = 0; j <= 12; ++j) {
            const double th = std::numbers::pi * j / 12, ph = 2 * std::numbers::pi * i / 24;
            const Vec3 u(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
            const glm::vec2 s =
                ndc(scene.render.camera.base, float(w) / float(h),
                    sim.state.x[book] + scale * (sim.state.q[book] * semi.cwiseProduct(u)));
            outline.push_back({(s.x * 0.5f + 0.5f) * w, (0.5f - 0.5f * s.y) * h});
        }
    // Well inside it (its rim trimmed by a pixel), the construction changes most pixels.
    const std::vector<bool> in = inside_outline(outline, w, h);
    long inner = 0, changed = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const std::size_t p = std::size_t(y) * w + std::size_t(x);
            if (!(in[p] && in[p - 1] && in[p + 1] && in[p - w] && in[p + w])) continue;
            ++inner;
            changed += !std::equal(a.rgb.begin() + 3 * p, a.rgb.begin() + 3 * p + 3,
                                   b.rgb.begin() + 3 * p);
        }
    ASSERT_GT(inner, 500);
    const double fraction = double(changed) / double(inner);
    TUMBLE_MEASURED(fraction, 0.9);
    EXPECT_GT(fraction, 0.9);
}

TEST(PoinsotCli, ABodyThatMayFeelATorqueIsWarnedAbout) {
    const auto dir = test::scratch_dir();
    const std::string still = " --frame 0 --width 160 --height 90 -o x.png";
    // The heavy top: its table pushes on its tip.
    const test::CliResult top =
        test::run_tumble(dir, "render lessons/top_precession --poinsot top" + still);
    EXPECT_EQ(top.exit_code, 0) << top.err;
    EXPECT_NE(top.err.find("tumble: warning: Poinsot's construction"), std::string::npos)
        << top.err;
    EXPECT_NE(top.err.find("\"top\""), std::string::npos) << top.err;
    EXPECT_NE(top.err.find("contacts"), std::string::npos) << top.err;
    // A constant applied torque, in empty space.
    test::write_text(dir / "torqued.json", R"({"format_version": 1,
      "world": {"gravity": [0, 0, 0], "duration": 1},
      "bodies": [{"name": "book", "shape": {"type": "box", "size": [0.22, 0.05, 0.30]},
                  "mass": 0.8, "angular_velocity": [6, 0.05, 0.05], "torque": [0, 0, 0.01]}]})");
    const test::CliResult torqued =
        test::run_tumble(dir, "render torqued.json --poinsot book" + still);
    EXPECT_EQ(torqued.exit_code, 0) << torqued.err;
    EXPECT_NE(torqued.err.find("applied torque"), std::string::npos) << torqued.err;
    // Lesson 4's book is torque-free: no warning.
    const test::CliResult free =
        test::run_tumble(dir, "render lessons/intermediate_axis --poinsot book" + still);
    EXPECT_EQ(free.exit_code, 0) << free.err;
    EXPECT_EQ(free.err.find("warning"), std::string::npos) << free.err;
    // The frame says so too.
    RenderCommand cmd;
    cmd.common.scene = "lessons/top_precession";
    cmd.common.quiet = true;
    cmd.poinsot = "top";
    Scene scene = load_for_command(cmd.common);
    apply_render_overrides(cmd, scene);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    Simulation sim = make_simulation(scene, tl.h);
    FrameSource frames(scene, tl, sim, 0, 0);
    render::SceneView view;
    ASSERT_TRUE(frames.next(view));
    EXPECT_TRUE(
        std::any_of(view.canvas.labels.begin(), view.canvas.labels.end(),
                    [](const auto& l) { return l.text.find("torque") != std::string::npos; }));
}

} // namespace
} // namespace tumble::app
