#pragma once
// A-posteriori estimate of a run's global error: step doubling with Richardson extrapolation
// (Hairer, Norsett and Wanner, "Solving Ordinary Differential Equations I", 2nd ed. 1993, II.4;
// docs/error-estimate.md says why this method and not an embedded pair or a reference run).
//
// A shadow State is stepped beside the main one with the same Model except the step, h/2: two
// shadow steps per main step, with the same integrator, the same contact settings and the same
// number of contact substeps per step (so every substep of the shadow is half the main one's too).
// For an integrator of order p the global error at a fixed time t is e_h(t) = C(t) h^p +
// O(h^(p+1)), so
//   y_h - y_{h/2} = e_h - e_{h/2} = C h^p (1 - 2^-p) + ...,   e_h(t) ~= (y_h - y_{h/2}) / (1 -
//   2^-p)
// and per dynamic body the estimate is
//   position     |x_h - x_{h/2}| / (1 - 2^-p)                              m (centre of mass)
//   orientation  angle of q_{h/2}^-1 (x) q_h, in [0, pi], / (1 - 2^-p)      rad
// p is the integrator's `order` in the registry (integrator.h); a method exact up to round-off
// (order <= 0) takes the raw difference (richardson_factor).
//
// The shadow only reads the main run's state; the main State is never written, so the main run is
// bit-identical with and without the estimate.
//
// Where it does not hold. The estimate is the integrator's error along smooth motion. The contact
// stage changes a body's motion by other rules (impulses, the solver's symplectic position update,
// sleeping), so a body's estimate stops holding at the start of the first step in which the contact
// stage acts on it in either run: it appears in a contact manifold (touching, or speculative:
// within 1 cm + h |relative speed| of another shape, physics/step.cpp), which is also how a
// neighbour in contact pushes it; or it is put to sleep (v = w = 0 and frozen, which the shadow
// would copy, so their difference would say nothing). Its estimate is then kept as it was at that
// time (the last free-flight one), with `limit` saying why and `valid_until` when.
#include "physics/model.h"
#include "physics/state.h"
#include "physics/step.h"
#include "physics/stop.h"

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace tumble::physics {

// 1 / (1 - 2^-p) for an integrator of order p >= 1; 1 for a method exact up to round-off (order
// <= 0: its two runs differ only by round-off, which is the estimate).
double richardson_factor(int order);

// One body's estimated global error.
struct BodyError {
    double rotation = 0.0; // rad, in [0, pi / (1 - 2^-p)]
    double position = 0.0; // m, of the centre of mass
};

// Why an estimate stopped holding.
enum class EstimateLimit : std::uint8_t {
    None,    // it holds
    Contact, // the contact stage acted on the body (a manifold with it, in either run)
    Sleep,   // the body was put to sleep (in either run) without a contact
};
const char* estimate_limit_name(EstimateLimit limit); // "", "contact", "sleep"

struct BodyEstimate {
    int body = -1; // handle into the Model
    BodyError at;  // at the estimate's time, or at valid_until once it no longer holds
    BodyError max; // the largest over every step while it held
    EstimateLimit limit = EstimateLimit::None;
    // The last time the estimate holds (s): the start of the first step in which a contact or sleep
    // touched the body; +infinity while it holds.
    double valid_until = std::numeric_limits<double>::infinity();
    bool holds() const { return limit == EstimateLimit::None; }
};

// The shadow run diverged (not finite, or an integrator's solve failed) while the main one did
// not: the run's error cannot be estimated. Never repaired; `step` is the shadow's step.
struct ShadowDivergenceError : DivergenceError {
    ShadowDivergenceError(const DivergenceError& e, std::int64_t main_step, const std::string& what)
        : DivergenceError(e.body, e.step, e.quantity, what), main_step(main_step) {}
    std::int64_t main_step;
};

// The incremental estimator for loops that step the main run themselves (render, simulate):
//   ErrorEstimator e(model, state);
//   for (...) { step(model, state); e.advance(state); }   // then e.bodies(), e.time()
class ErrorEstimator {
  public:
    // `initial` is the main run's state at the start (any step); the shadow starts as its copy.
    // `threads` as StepWorkspace's (the shadow has a workspace of its own).
    ErrorEstimator(const Model& model, const State& initial, int threads = 1);

    // Steps the shadow twice (to the main run's new time), checks both runs for contacts and
    // sleep, and estimates every body that still holds. Call once after each main step, with the
    // main state: throws std::logic_error if it is not exactly one step on from the last call,
    // ShadowDivergenceError if the shadow diverges.
    void advance(const State& main);

    // One per dynamic body, in Model::dynamic_bodies order.
    std::span<const BodyEstimate> bodies() const { return bodies_; }
    double time() const { return static_cast<double>(main_step_) * dt_; } // s, of the estimate
    std::int64_t main_step() const { return main_step_; }
    int order() const { return order_; }
    double factor() const { return factor_; } // richardson_factor(order())
    const State& shadow() const { return shadow_; }
    const Model& shadow_model() const { return shadow_model_; }

  private:
    void step_shadow();
    void note_limits(const State& s, std::int64_t main_step);
    void estimate(const State& main);

    Model shadow_model_;
    State shadow_;
    StepWorkspace workspace_;
    std::vector<BodyEstimate> bodies_;
    std::vector<int> slot_; // per body: its index in bodies_, or -1 (static)
    double dt_;             // the main run's step
    int order_;
    double factor_;
    std::int64_t main_step_;
};

// The shadow's model: `model` at h/2 with the same number of contact substeps per step.
Model half_step_model(const Model& model);

// A whole run with its estimate, for pilots and the study.
struct EstimateSample {
    double t = 0.0;                  // s
    std::vector<BodyError> at;       // per dynamic body (as in RunEstimate::bodies)
    std::vector<std::uint8_t> holds; // per dynamic body: 1 while its estimate holds
};

struct RunEstimate {
    State final_state;                   // the main run's, as step() alone gives it
    std::vector<BodyEstimate> bodies;    // at the end, with their maxima and limits
    std::vector<EstimateSample> samples; // every sample_every steps and at the end
};

// Steps `initial` `steps` times with `model`, estimating as it goes. Throws what step() throws
// (DivergenceError of the main run), ShadowDivergenceError, and Stopped when `stop` asks
// (stop.h). `sample_every` >= 1.
RunEstimate estimate_run(const Model& model, const State& initial, std::int64_t steps,
                         std::int64_t sample_every, const StopCheck& stop = {});

} // namespace tumble::physics
