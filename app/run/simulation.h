#pragma once
// A scene made ready to step: the physics model, its initial state and the step's workspace.
#include "app/run/run_estimate.h"
#include "app/scene/scene.h"
#include "physics/effort_tally.h"
#include "physics/model.h"
#include "physics/state.h"
#include "physics/step.h"

#include <memory>
#include <string>
#include <vector>

namespace tumble::app {

struct Simulation {
    physics::Model model;
    physics::State state;
    // The contact stage's buffers and worker threads (physics/step.h). States do not depend on
    // the thread count: the same scene gives the same bits with 1 or N threads.
    std::unique_ptr<physics::StepWorkspace> workspace;
    std::string source;                  // the scene's file, named in the message of a divergence
    std::vector<std::string> body_names; // as the scene names them, in the same message
    // The error estimate, when start_error_estimate() turned it on (app/run/run_estimate.h).
    SimulationEstimate estimate;
    // The contact solver's effort, step by step (physics/effort_tally.h), for the run summary.
    physics::EffortTally effort;

    // One physics step (and the estimate's shadow steps). Throws physics::DivergenceError (or
    // physics::ShadowDivergenceError), its message starting with `source` and naming the body as
    // the scene does (`body 0 "rocket"`).
    void step();
};

// Builds the model with time step `dt` (the scene's, or one adjusted to hit frame times) and a
// workspace of `threads` threads (only a scene with contacts uses more than one). Throws
// SceneError as build_checked() (app/scene/scene_check.h) does.
Simulation make_simulation(const Scene& scene, double dt, int threads = 1);

// The run summary's line on the contact solver's effort (substeps and sweeps per island), or ""
// for a scene without contacts.
std::string effort_summary(const Simulation& sim);

// Why a run asked for `threads` > 1 physics threads steps on one: the scene has no contact stage,
// or fewer dynamic bodies than world.parallel_min_bodies. Empty if the threads are used.
std::string threads_note(const Simulation& sim, int threads);

} // namespace tumble::app
