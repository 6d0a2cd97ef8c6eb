#pragma once
// One way to prepare a run (docs/architecture.md, "The flow of one run"). Every command that runs
// a scene (render, simulate, explain, compare, the render benchmark, `tumble test`, checkpoints,
// shards, the Python module) goes scene -> RunPlan -> Simulation here, so that one scene gives one
// integrator, one step, one timeline and so one trajectory, whichever command runs it:
//   1. plan_run(): world.integrator "auto" becomes an integrator and a step for the scene's frame
//      rate (its pilot runs, physics/accuracy_plan.h), then the timeline (frame k at t = k / fps,
//      a whole number of steps h per frame, app/run/timeline.h);
//   2. start_run(): the physics model and the state at t = 0, with the error estimate riding
//      along when the scene asks for it (app/run/run_estimate.h);
//   3. frame_automatically(plan.scene, plan.timeline): camera.auto's pre-pass over the planned run
//      (app/run/auto_camera.h), apart because a command runs it only once its outputs are known
//      to be good (a bad output name is exit 2 before any stepping).
// prepare_run() does 1 and 2.
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"

#include <string>
#include <vector>

namespace tumble::app {

// A scene as it will run: "auto" resolved (world.integrator and world.dt are the plan's, the plan
// kept in scene.accuracy.plan) and its timeline.
struct RunPlan {
    Scene scene;
    Timeline timeline;
};

struct RunOptions {
    int threads = 1;            // physics threads of the contact stage (the same bits for any)
    bool error_estimate = true; // start the estimate if the scene asks for it (false: a pre-pass)
};

struct PreparedRun {
    Scene scene;
    Timeline timeline;
    Simulation sim; // at t = 0

    // What every command that steps the scene prints: the timeline's adjustment of the scene's
    // dt and why --threads are not used. Empty strings left out.
    std::vector<std::string> notes(int threads) const;
};

// Step 1. The scene's render.fps sets the frame times, so apply --fps before. Throws SceneError
// when no integrator meets the tolerance, and what stepping throws from a pilot run.
RunPlan plan_run(Scene scene);

// Step 2, for a planned scene and its timeline (also each lane of --compare, each pass of a
// suite, each pre-pass).
Simulation start_run(const Scene& scene, const Timeline& timeline, const RunOptions& options = {});

// Steps 1 and 2.
PreparedRun prepare_run(Scene scene, const RunOptions& options = {});

} // namespace tumble::app
