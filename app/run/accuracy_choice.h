#pragma once
// Accuracy as a setting, in a run: world.integrator "auto" (or --tolerance) becomes an integrator
// and a step before anything steps (physics/accuracy_plan.h), and the run says what it chose, why,
// and whether the tolerance was met (docs/accuracy.md).
#include "app/scene/scene.h"
#include "physics/accuracy_plan.h"

#include <string>
#include <vector>

namespace tumble::app {

// When the scene asks for "auto": plans its whole duration at steps h = 1 / (fps k) (so that steps
// land on frame times), keeps the plan in scene.accuracy.plan and sets scene.world.integrator and
// scene.world.dt to the plan's. Throws SceneError naming the tolerance's place when no integrator
// meets it within the step limit. Changes nothing for a scene with a named integrator.
void resolve_auto_integrator(Scene& scene);

// What was chosen and why, one line each: for `tumble explain` (every pilot) and the run summary
// (`brief`: the choice and the pilots' cost).
// Empty unless the scene's plan is set.
std::vector<std::string> describe_choice(const Scene& scene, bool brief);

// After a run with an estimate: one line saying whether each body met the tolerance ("met" or a
// warning naming body, quantity and amount), and bodies whose estimate stopped holding.
struct ToleranceCheck {
    bool met = true;
    std::vector<std::string> lines;
};
ToleranceCheck check_tolerance(const physics::Tolerance& tol,
                               const std::vector<physics::BodyEstimate>& estimate,
                               const std::vector<std::string>& body_names);

struct Simulation;

// After a run with a tolerance: prints check_tolerance()'s lines to stderr ("tumble: tolerance ...
// met", or "tumble: warning: ..." naming body and amount). Nothing without a tolerance.
void report_tolerance(const Scene& scene, const Simulation& sim);

} // namespace tumble::app
