#pragma once
// The physics side of checking a scene: the model builder's validation (physics/build.h) mapped
// to the scene file's JSON paths, and what is legal but probably unintended. The scene loader
// runs both on every scene; `run` builds its Simulation from the same checked model.
#include "app/scene/scene.h"
#include "physics/model.h"
#include "physics/state.h"

#include <string>
#include <vector>

namespace tumble::app {

struct CheckedStart {
    physics::Model model;
    physics::State state; // at t = 0
};

// physics::build_model with step `dt` (the scene's, or one adjusted to hit frame times) and
// physics::initial_state. Validation errors of either become SceneError at the JSON path of the
// offending field, with the bodies the message mentions named as the scene names them.
CheckedStart build_checked(const Scene& scene, double dt);

// `what` (a physics message) with each "body 3" as `body 3 "left wall"`, `names` being the
// bodies' names as the scene gives them (BodyLook::name), so the user sees the names they wrote.
std::string with_body_names(const std::vector<std::string>& names, const std::string& what);

// Warnings about the initial state that do not stop the run: pairs of bodies starting deeply
// interpenetrated (physics::deep_initial_overlaps), each naming both bodies.
std::vector<std::string> initial_state_warnings(const Scene& scene, const physics::Model& model,
                                                const physics::State& state);

} // namespace tumble::app
