// Step doubling with Richardson extrapolation (error_estimate.h has the derivation).
#include "physics/error_estimate.h"

#include "physics/integrator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tumble::physics {

double richardson_factor(int order) {
    if (order <= 0) return 1.0;
    return 1.0 / (1.0 - std::ldexp(1.0, -order));
}

const char* estimate_limit_name(EstimateLimit limit) {
    switch (limit) {
    case EstimateLimit::None:
        return "";
    case EstimateLimit::Contact:
        return "contact";
    case EstimateLimit::Sleep:
        return "sleep";
    }
    return "";
}

Model half_step_model(const Model& model) {
    Model m = model;
    // The substep count is fixed before the step is halved: with the automatic rate (1440 per
    // second) the shadow would otherwise take half as many substeps of the same length, and bodies
    // integrated in substeps would show no difference between the runs.
    // (Effort on demand integrates free bodies over the whole step, so the shadow's are at h/2.)
    if (fixed_effort(model.contact)) m.contact.substeps = substep_count(model.contact, model.dt);
    m.dt = 0.5 * model.dt;
    return m;
}

ErrorEstimator::ErrorEstimator(const Model& model, const State& initial, int threads)
    : shadow_model_(half_step_model(model)), shadow_(initial), workspace_(threads), dt_(model.dt),
      order_(integrator_info(model.integrator).order), factor_(richardson_factor(order_)),
      main_step_(initial.step) {
    shadow_.step = 2 * initial.step; // the same time t = step * dt at h/2
    slot_.assign(model.body_count(), -1);
    for (int i : model.dynamic_bodies) {
        slot_[i] = static_cast<int>(bodies_.size());
        bodies_.push_back(
            BodyEstimate{i, {}, {}, EstimateLimit::None, std::numeric_limits<double>::infinity()});
    }
    // A body already in contact or asleep at the start has no free flight to estimate.
    note_limits(initial, main_step_ + 1);
}

void ErrorEstimator::step_shadow() {
    try {
        step(shadow_model_, shadow_, workspace_);
    } catch (const DivergenceError& e) {
        throw ShadowDivergenceError(
            e, main_step_ + 1,
            "error estimate: the shadow run (the same scene at h/2 = " + std::to_string(0.5 * dt_) +
                " s, for step doubling) diverged while the run itself did not, at main step " +
                std::to_string(main_step_ + 1) + ": " + e.what() +
                "; the run's error cannot be estimated (run without the estimate, or with a "
                "smaller dt)");
    }
}

// Bodies in a manifold of `s`'s contacts (found at the start of the step that made `s`, and acted
// on during it) or asleep in `s` stop holding; their estimate stays the one of main step
// `main_step` - 1, the start of the step in which this happened.
void ErrorEstimator::note_limits(const State& s, std::int64_t main_step) {
    const double start = static_cast<double>(main_step - 1) * dt_;
    auto limit = [&](int body, EstimateLimit why) {
        const int k = body >= 0 && body < static_cast<int>(slot_.size()) ? slot_[body] : -1;
        if (k < 0 || !bodies_[k].holds()) return;
        bodies_[k].limit = why;
        bodies_[k].valid_until = start;
    };
    const ContactCache& c = s.contacts;
    for (int m = 0; m < c.size(); ++m) {
        limit(pair_first(c.pair[m]), EstimateLimit::Contact);
        limit(pair_second(c.pair[m]), EstimateLimit::Contact);
    }
    for (std::size_t i = 0; i < s.sleep.asleep.size(); ++i)
        if (s.sleep.asleep[i]) limit(static_cast<int>(i), EstimateLimit::Sleep);
}

void ErrorEstimator::estimate(const State& main) {
    for (BodyEstimate& b : bodies_) {
        if (!b.holds()) continue;
        const int i = b.body;
        b.at.position = factor_ * (main.x[i] - shadow_.x[i]).norm();
        b.at.rotation = factor_ * rotation_angle_between(shadow_.q[i], main.q[i]);
        b.max.position = std::max(b.max.position, b.at.position);
        b.max.rotation = std::max(b.max.rotation, b.at.rotation);
    }
}

void ErrorEstimator::advance(const State& main) {
    if (main.step != main_step_ + 1)
        throw std::logic_error("error estimate: expected the main run at step " +
                               std::to_string(main_step_ + 1) + ", got step " +
                               std::to_string(main.step) +
                               " (a restored or skipped state: the shadow run cannot follow it)");
    for (int k = 0; k < 2; ++k) {
        step_shadow();
        note_limits(shadow_, main.step);
    }
    note_limits(main, main.step);
    main_step_ = main.step;
    estimate(main);
}

RunEstimate estimate_run(const Model& model, const State& initial, std::int64_t steps,
                         std::int64_t sample_every, const StopCheck& stop) {
    if (sample_every < 1) throw std::invalid_argument("estimate_run: sample_every must be >= 1");
    RunEstimate out;
    out.final_state = initial;
    State& s = out.final_state;
    ErrorEstimator e(model, initial);
    StepWorkspace workspace(1);
    for (std::int64_t k = 1; k <= steps; ++k) {
        poll_stop(stop, k);
        step(model, s, workspace);
        e.advance(s);
        if (k % sample_every != 0 && k != steps) continue;
        EstimateSample sample;
        sample.t = e.time();
        for (const BodyEstimate& b : e.bodies()) {
            sample.at.push_back(b.at);
            sample.holds.push_back(b.holds() ? 1 : 0);
        }
        out.samples.push_back(std::move(sample));
    }
    out.bodies.assign(e.bodies().begin(), e.bodies().end());
    return out;
}

} // namespace tumble::physics
