#pragma once
// Runs a scene of the shared library (physics/scenes) in the physics tests: its model and state,
// stepped on one thread.
#include "physics/build.h"
#include "physics/scenes/scene.h"
#include "physics/step.h"

#include <cmath>

namespace tumble::physics::test {

struct Sim {
    Model model;
    State state;
    explicit Sim(const scenes::Scene& s) : model(build_model(s.world, s.bodies)) {
        state = initial_state(model, s.bodies);
    }
    void steps(int n) {
        for (int k = 0; k < n; ++k) step(model, state);
    }
    int steps_for(double seconds) const {
        return static_cast<int>(std::lround(seconds / model.dt));
    }
};

} // namespace tumble::physics::test
