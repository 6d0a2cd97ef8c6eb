#pragma once
// A scene made ready to step: the physics model and its initial state.
#include "app/scene.h"
#include "physics/model.h"
#include "physics/state.h"

namespace tumble::app {

struct Simulation {
    physics::Model model;
    physics::State state;
};

// Builds the model with time step `dt` (the scene's, or one adjusted to hit frame times).
// Physics validation errors become SceneError at the JSON path of the offending field.
Simulation make_simulation(const Scene& scene, double dt);

} // namespace tumble::app
