#pragma once
// Accuracy as a setting: the cheapest (integrator, step) that meets a tolerance over a run's whole
// duration, chosen by pilot runs with the step-doubling estimate (error_estimate.h).
//
// The run's steps must land on its sample times (a video's frames), so a step is h = base / k for a
// whole k >= 1 (base: the frame interval). For each candidate integrator, of order p and relative
// cost c per body-step (IntegratorInfo::cost), the plan runs the whole duration at k = 1 with the
// estimate and reads the largest normalised error over every step and body,
//   E(k) = max over steps and bodies of max(rotation / tol_rotation, position / tol_position).
// The global error of an order-p method scales as h^p, so E(k') ~= E(k) (k / k')^p: the next pilot
// is at the k' that puts E at kTarget (half the tolerance), and a pilot is accepted when its E <=
// kAccept. The duration is never shortened: near the intermediate axis's separatrix an energy error
// becomes an error in the time of every flip, which grows with t, so a method that is cheapest
// over 2.5 s can be far off over 20 s; only a pilot over the whole run sees that. The search is
// best first: the next pilot is always the cheapest pending one over all integrators, and pilots
// that would cost at least the best accepted plan are not run (they cannot win), so the pilots cost
// a few times the plan.
//
// Cost of a plan = steps x (sum over dynamic bodies of c) [+ the contact stage's share, when the
// scene has one]: a model of the stepping time measured by `tumble study`, deterministic, so that
// the same scene always gets the same plan (the determinism promise); `tumble study --auto`
// measures real times and checks the plans against the study's grid.
//
// Where the estimate does not hold (bodies in contact: error_estimate.h), the plan meets the
// tolerance on what the estimate covers - every body until its first contact - and says which
// bodies and times are not covered.
#include "physics/error_estimate.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/state.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tumble::physics {

struct Tolerance {
    double rotation = 1e-4; // rad, on each body's orientation
    double position = 1e-4; // m, on each body's centre of mass
};

// Normalised error of one estimate: max(rotation / tol.rotation, position / tol.position); <= 1
// meets the tolerance.
double normalised_error(const BodyError& e, const Tolerance& tol);

// One pilot run.
struct PlanTrial {
    Integrator integrator = Integrator::Rk4;
    int k = 1;              // h = base / k
    std::int64_t steps = 0; // over the whole duration
    double cost = 0.0;      // the cost model's units (body-steps of symplectic_euler)
    double error = 0.0;     // E: largest normalised estimate over steps and covered bodies
    bool diverged = false;  // the run or its shadow diverged (E is then infinite)
    bool accepted = false;  // E <= kAccept
};

struct AccuracyPlan {
    bool found = false; // some candidate met the tolerance within the step limit
    Integrator integrator = Integrator::Rk4;
    int k = 1;
    double h = 0.0;                     // s
    double cost = 0.0;                  // of the chosen run
    double error = 0.0;                 // E of the chosen pilot
    std::vector<BodyEstimate> estimate; // the chosen pilot's, per dynamic body
    std::vector<PlanTrial> trials;      // every pilot, in the order run
    std::vector<std::string> skipped;   // "exact: the scene applies torques", ...
};

struct PlanSettings {
    double target = 0.5; // kTarget: where a predicted step puts E
    double accept = 0.8; // kAccept: a pilot is accepted at E <= accept
    int min_k = 1;       // h <= base / min_k (contacts: the scene's own step, accuracy_choice.h)
    int max_k = 1 << 20; // h >= base / max_k
    int max_pilots_per_integrator = 6;
    std::vector<Integrator> only; // the candidates; empty: every integrator of the registry
    StopCheck stop;               // polled during each pilot (stop.h): Ctrl-C
};

// Plans a run of `model` (its integrator and dt are ignored) from `initial` over base_steps steps
// of `base` seconds. Throws ModelError for a model no integrator can estimate (no dynamic body),
// Stopped when settings.stop asks.
AccuracyPlan plan_accuracy(const Model& model, const State& initial, double base,
                           std::int64_t base_steps, const Tolerance& tol,
                           const PlanSettings& settings = {});

// The cost model of a run: steps x per-step cost of `integrator` on `model`.
double run_cost(const Model& model, Integrator integrator, std::int64_t steps);

// Why `integrator` cannot step `model` (empty if it can): e.g. `exact` under torques.
std::string integrator_refusal(const Model& model, Integrator integrator);

} // namespace tumble::physics
