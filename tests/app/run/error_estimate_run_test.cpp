// The error estimate riding along a Simulation (app/run/run_estimate.h): it reaches the overlay of
// each frame FrameSource makes, keeps the estimates of the chosen times as they were at their
// step, and leaves the run's states as they are without it.
#include "app/run/frame_source.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "physics/scenes/state_hash.h"

#include <gtest/gtest.h>

namespace tumble::app {
namespace {

// The default scene's floating book (no gravity) and one ball dropped onto the ground.
Scene scene(const std::string& estimate) {
    return load_scene(R"({"format_version": 1,
      "world": {"duration": 2, "error_estimate": )" +
                          estimate + R"(},
      "render": {"overlay": true},
      "bodies": [
        {"name": "ground", "shape": {"type": "plane"}},
        {"name": "book", "shape": {"type": "box", "size": [0.22, 0.05, 0.30]}, "mass": 0.8,
         "position": [0, 0, 1.35], "gravity_scale": 0, "angular_velocity": [0.05, 6, 0.05]},
        {"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "position": [1, 0, 1.1]}]})",
                      "drop.json");
}

TEST(ErrorEstimateRun, TheOverlayShowsTheEstimateOfEachFrame) {
    const Scene s = scene("true");
    const Timeline tl = make_timeline(s.world.dt, s.duration, s.render.fps);
    Simulation sim = make_simulation(s, tl.h);
    start_error_estimate(sim, s);
    FrameSource frames(s, tl, sim, 0, 60);
    render::SceneView view;
    ASSERT_TRUE(frames.next(view)); // frame 0: nothing to estimate yet
    EXPECT_EQ(view.overlay.back(), "err <= 0.0e+00 rad, 0.0e+00 m (step doubling)");
    for (int k = 1; k <= 60; ++k) ASSERT_TRUE(frames.next(view)); // to frame 60, t = 1 s
    // At t = 1 s the ball (dropped from 1 m) has landed: one body no longer holds.
    EXPECT_EQ(view.overlay.back().find("err <= "), 0u) << view.overlay.back();
    EXPECT_NE(view.overlay.back().find("; n/a for 1"), std::string::npos) << view.overlay.back();
}

TEST(ErrorEstimateRun, ChosenTimesKeepTheirEstimateAndTheStatesAreUnchanged) {
    const Scene with = scene(R"({"times": [0.5, 1.5]})"), without = scene("false");
    Simulation a = make_simulation(with, with.world.dt), b = make_simulation(without, 1.0 / 240);
    start_error_estimate(a, with);
    start_error_estimate(b, without);
    EXPECT_FALSE(b.estimate.estimator);
    ASSERT_EQ(a.estimate.times.size(), 2u);
    EXPECT_EQ(a.estimate.times[0].step, 120); // round(0.5 s / (1/240 s))
    double at_half = 0.0;
    for (int k = 0; k < 480; ++k) {
        a.step();
        b.step();
        if (k + 1 == 120) at_half = a.estimate.estimator->bodies()[0].at.rotation;
    }
    EXPECT_EQ(scenes::state_hash(a.state), scenes::state_hash(b.state));
    EXPECT_TRUE(a.estimate.times[0].reached);
    EXPECT_EQ(a.estimate.times[0].bodies[0].at.rotation, at_half);
    EXPECT_GT(a.estimate.estimator->bodies()[0].at.rotation, at_half); // the error grows
    const std::vector<std::string> lines = estimate_summary(a);
    ASSERT_EQ(lines.size(), 3u); // the method, the book, the ball
    EXPECT_NE(lines[2].find("\"ball\": does not hold after t = "), std::string::npos) << lines[2];
    EXPECT_NE(lines[2].find("t = 1.5 s: does not hold"), std::string::npos) << lines[2];
}

} // namespace
} // namespace tumble::app
