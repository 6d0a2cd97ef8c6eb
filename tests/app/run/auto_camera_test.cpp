// camera.auto (issue 14): one fixed camera that keeps every dynamic body in view for the whole
// run, steady, upright along the scene's up axis; what a scene without a camera gets. Checked
// here with the test's own projection (glm::lookAt / glm::perspective) of each body's bounding
// sphere at every frame, on a run stepped independently of the pre-pass.
#include "app/run/auto_camera.h"
#include "app/run/simulation.h"
#include "app/scene/scene_error.h"
#include "physics/can_touch.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>

namespace tumble::app {
namespace {

// A book thrown up and across, landing and sliding: 3 s, no camera given.
const char* kThrown = R"({"format_version": 1, "world": {"duration": 3},
  "render": {"width": 320, "height": 180, "fps": 30},
  "bodies": [{"name": "ground", "shape": {"type": "plane"}},
             {"name": "book", "shape": {"type": "box", "size": [0.2, 0.05, 0.3]},
              "position": [0, 0, 1], "velocity": [2, 0.5, 4], "angular_velocity": [1, 6, 0.1]},
             {"name": "ball", "shape": {"type": "sphere", "radius": 0.1},
              "position": [-1, 1, 0.1], "velocity": [-1, 0, 0]}]})";

// The screen extent of every dynamic body over every frame: NDC x and y of the bounding
// sphere's extreme points (centre +- R along the camera's right and up).
struct Extent {
    double lo_x = 1e9, hi_x = -1e9, lo_y = 1e9, hi_y = -1e9;
    bool behind = false;
};

Extent screen_extent(const Scene& scene, const render::Camera& cam) {
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    Simulation sim = make_simulation(scene, tl.h);
    const glm::dmat4 view =
        glm::lookAt(glm::dvec3(cam.position), glm::dvec3(cam.target), glm::dvec3(cam.up));
    const double aspect = double(scene.render.width) / scene.render.height;
    const glm::dmat4 proj =
        glm::perspective(glm::radians(double(cam.fov_y_deg)), aspect, 0.01, 1000.0);
    const glm::dvec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::dvec3 up(view[0][1], view[1][1], view[2][1]);
    Extent e;
    for (std::int64_t k = 0; k < tl.frames; ++k) {
        if (k > 0)
            for (int s = 0; s < tl.steps_per_frame; ++s) sim.step();
        for (int i : sim.model.dynamic_bodies) {
            const double r = physics::bounding_radius(sim.model, i);
            const glm::dvec3 x(sim.state.x[i].x(), sim.state.x[i].y(), sim.state.x[i].z());
            for (const glm::dvec3& p : {x + r * right, x - r * right, x + r * up, x - r * up}) {
                const glm::dvec4 c = proj * view * glm::dvec4(p, 1.0);
                if (c.w <= 0.0) e.behind = true;
                e.lo_x = std::min(e.lo_x, c.x / c.w), e.hi_x = std::max(e.hi_x, c.x / c.w);
                e.lo_y = std::min(e.lo_y, c.y / c.w), e.hi_y = std::max(e.hi_y, c.y / c.w);
            }
        }
    }
    return e;
}

TEST(AutoCamera, ASceneWithoutACameraKeepsEveryBodyInViewForTheWholeRun) {
    Scene scene = load_scene(kThrown, "thrown.json");
    EXPECT_EQ(scene.render.camera.mode, CameraRig::Mode::Auto);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    frame_automatically(scene, tl);
    ASSERT_EQ(scene.render.camera.mode, CameraRig::Mode::Fixed); // one camera for the whole run
    const render::Camera cam = scene.render.camera.base;
    EXPECT_EQ(cam.up, glm::vec3(0, 0, 1)); // against gravity
    const Extent e = screen_extent(scene, cam);
    std::printf("[measured] NDC x [%.3f, %.3f], y [%.3f, %.3f]\n", e.lo_x, e.hi_x, e.lo_y, e.hi_y);
    EXPECT_FALSE(e.behind);
    // In view with the margin: 10% of the half-frame free on every side (1 / 1.1 = 0.909).
    for (double v : {e.lo_x, e.lo_y}) EXPECT_GE(v, -0.91);
    for (double v : {e.hi_x, e.hi_y}) EXPECT_LE(v, 0.91);
    // And framed, not lost in the distance: the motion fills the frame in one direction at least.
    EXPECT_GT(std::max(e.hi_x - e.lo_x, e.hi_y - e.lo_y), 1.5);
}

// A box seen along x: the camera stands back until its nearest face's corners reach the margin.
TEST(AutoCamera, FrameBoxPutsTheTightestCornerOnTheMargin) {
    const render::Camera c = frame_box(glm::dvec3(-1, -1, -1), glm::dvec3(1, 1, 1),
                                       glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), 90.0, 1.0, 0.0);
    // tan(45 deg) = 1: the corner at depth D - 1 with |y|, |z| = 1 needs D - 1 = 1.
    EXPECT_NEAR(c.position.x, 2.0f, 1e-6f);
    EXPECT_NEAR(c.position.y, 0.0f, 1e-6f);
    EXPECT_EQ(c.target, glm::vec3(0.0f));
}

TEST(AutoCamera, AutoWithAPositionIsRefusedByPath) {
    const std::string bad = std::string(kThrown).replace(
        std::string(kThrown).find("\"fps\": 30}"), 10,
        "\"fps\": 30, \"camera\": {\"auto\": true, \"position\": [1, 2, 3]}}");
    try {
        load_scene(bad, "bad.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("/render/camera"), std::string::npos) << what;
        EXPECT_NE(what.find("\"direction\""), std::string::npos) << what;
    }
}

} // namespace
} // namespace tumble::app
