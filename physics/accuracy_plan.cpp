// The cheapest (integrator, step) for a tolerance: pilots with the step-doubling estimate
// (accuracy_plan.h explains the search and its cost model).
#include "physics/accuracy_plan.h"

#include "physics/build.h"
#include "physics/step.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::physics {
namespace {

// The contact stage's share of a body-step, in the cost model's units (a body-step of
// symplectic_euler, 69 ns): 1000 spheres raining on a plane step at 297 steps/s, 3.4 us per
// body-step with the integrator's ~0.1 us included (docs/contacts.md,
// scripts/bench-sphere-rain.sh), so about 50 units. Only its size matters: with contacts, fewer
// steps win whatever the integrator.
constexpr double kContactBodyStepCost = 50.0;

// E over every step while each body's estimate held: the largest of the per-body maxima.
double largest_error(const std::vector<BodyEstimate>& bodies, const Tolerance& tol) {
    double e = 0.0;
    for (const BodyEstimate& b : bodies) e = std::max(e, normalised_error(b.max, tol));
    return e;
}

struct Pilot {
    PlanTrial trial;
    std::vector<BodyEstimate> estimate;
};

Pilot run_pilot(const Model& model, const State& initial, Integrator id, int k, double base,
                std::int64_t base_steps, const Tolerance& tol, const StopCheck& stop) {
    Model m = model;
    m.integrator = id;
    m.dt = base / k;
    Pilot p;
    p.trial.integrator = id;
    p.trial.k = k;
    p.trial.steps = base_steps * k;
    p.trial.cost = run_cost(model, id, p.trial.steps);
    try {
        RunEstimate r = estimate_run(m, initial, p.trial.steps, p.trial.steps, stop);
        p.trial.error = largest_error(r.bodies, tol);
        p.estimate = std::move(r.bodies);
    } catch (const DivergenceError&) {
        // The main run or its shadow blew up: this step is far too long for this method. The
        // pilot says so (diverged, E infinite) and the search refines; the chosen run never
        // diverges, since only accepted pilots are chosen.
        p.trial.diverged = true;
        p.trial.error = std::numeric_limits<double>::infinity();
    }
    return p;
}

// The k' that puts E at `target` if E(k) ~ k^-p; a step that diverged or an error beyond the
// asymptotic range (E of order 1 rad / tol means the orientation is simply wrong) is refined by 8.
int next_k(int k, double error, int order, const PlanSettings& s) {
    const double p = order > 0 ? order : 1.0;
    double factor = 8.0;
    if (std::isfinite(error) && error < 1e12) factor = std::pow(error / s.target, 1.0 / p);
    const double next = std::ceil(k * std::clamp(factor, 1.1, 1e6));
    return static_cast<int>(std::min<double>(next, s.max_k + 1.0));
}

// One integrator's search: the k of its next pilot.
struct Search {
    Integrator id;
    int k = 1;
    int pilots = 0;
    bool done = false;
};

double pilot_cost(const Model& model, const Search& c, std::int64_t base_steps) {
    return run_cost(model, c.id, base_steps * c.k);
}

std::vector<Search> candidates(const Model& model, const PlanSettings& settings,
                               std::vector<std::string>& skipped) {
    std::vector<Search> out;
    for (const IntegratorInfo& info : integrators()) {
        if (!settings.only.empty() &&
            std::find(settings.only.begin(), settings.only.end(), info.id) == settings.only.end())
            continue;
        if (std::string why = integrator_refusal(model, info.id); !why.empty()) {
            skipped.push_back(std::string(info.name) + ": " + why);
            continue;
        }
        out.push_back(Search{info.id, std::max(1, settings.min_k)});
    }
    return out;
}

} // namespace

double normalised_error(const BodyError& e, const Tolerance& tol) {
    return std::max(e.rotation / tol.rotation, e.position / tol.position);
}

double run_cost(const Model& model, Integrator integrator, std::int64_t steps) {
    double per_body = integrator_info(integrator).cost;
    if (model.passes.contacts) per_body += kContactBodyStepCost;
    return per_body * static_cast<double>(model.dynamic_bodies.size()) * static_cast<double>(steps);
}

std::string integrator_refusal(const Model& model, Integrator integrator) {
    if (!integrator_info(integrator).refuses_torque) return {};
    for (int i : model.dynamic_bodies)
        if (model.applied_torque[i] != Vec3::Zero())
            return "body " + std::to_string(i) + " has an applied torque (torque-free bodies only)";
    return {};
}

AccuracyPlan plan_accuracy(const Model& model, const State& initial, double base,
                           std::int64_t base_steps, const Tolerance& tol,
                           const PlanSettings& settings) {
    if (model.dynamic_bodies.empty())
        throw ModelError(-1, "integrator", "\"auto\" needs a dynamic body to estimate");
    AccuracyPlan plan;
    std::vector<Search> open = candidates(model, settings, plan.skipped);
    double best = std::numeric_limits<double>::infinity();
    // Best first: always the cheapest pending pilot, so that the pilots never cost much more than
    // the plan they find. A pilot that costs at least the best accepted plan cannot win.
    for (;;) {
        Search* next = nullptr;
        for (Search& c : open)
            if (!c.done &&
                (!next || pilot_cost(model, c, base_steps) < pilot_cost(model, *next, base_steps)))
                next = &c;
        if (!next || pilot_cost(model, *next, base_steps) >= best) break;
        Pilot p =
            run_pilot(model, initial, next->id, next->k, base, base_steps, tol, settings.stop);
        p.trial.accepted = !p.trial.diverged && p.trial.error <= settings.accept;
        plan.trials.push_back(p.trial);
        ++next->pilots;
        if (p.trial.accepted) {
            best = p.trial.cost;
            plan.found = true;
            plan.integrator = next->id;
            plan.k = next->k;
            plan.h = base / next->k;
            plan.cost = p.trial.cost;
            plan.error = p.trial.error;
            plan.estimate = std::move(p.estimate);
            next->done = true;
            continue;
        }
        next->k = next_k(next->k, p.trial.error, integrator_info(next->id).order, settings);
        next->done = next->pilots >= settings.max_pilots_per_integrator || next->k > settings.max_k;
    }
    return plan;
}

} // namespace tumble::physics
