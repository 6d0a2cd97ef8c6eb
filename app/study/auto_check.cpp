// `tumble study --auto`: plans checked against the exact oracles (auto_check.h).
#include "app/study/auto_check.h"

#include "io/interrupt.h"

#include "app/study/metrics.h"
#include "app/study/report.h"
#include "app/study/runner.h"
#include "physics/accuracy_plan.h"
#include "physics/error_estimate.h"
#include "physics/step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace tumble::app::study {
namespace {

bool has_oracle(const Problem& p) {
    return p.reference == ReferenceKind::Exact || p.reference == ReferenceKind::Analytic;
}

double worst(const physics::BodyError& e) {
    return std::max(e.rotation, e.position);
}

// The chosen run, stepped with its estimate and compared with the reference at every sample.
void measure_choice(const Problem& p, const Setup& s, const Reference& ref, AutoCase& c,
                    physics::Integrator id, int k) {
    physics::Model m = s.model;
    m.integrator = id;
    m.dt = p.duration / (static_cast<double>(kSamples) * k);
    physics::State st = s.state;
    physics::StepWorkspace ws(1);
    physics::ErrorEstimator est(m, st);
    for (int j = 1; j <= kSamples; ++j) {
        for (int i = 0; i < k; ++i) {
            physics::step(m, st, ws);
            est.advance(st);
        }
        const Errors e = measure(m, st, ref.states[j], ref.diagnostics[j]);
        c.truth = std::max({c.truth, e.orientation, e.position});
        for (const physics::BodyEstimate& b : est.bodies()) {
            c.estimate = std::max(c.estimate, worst(b.at));
            if (!b.holds()) c.covered = false;
        }
    }
}

// Median measured ns / body-step of `integrator` on the problem's grid rows.
double measured_ns(const std::vector<Row>& grid, const Problem& p, const std::string& integrator) {
    std::vector<double> ns;
    for (const Row& r : grid)
        if (r.problem == p.name && r.integrator == integrator && r.ns_per_body_step > 0.0)
            ns.push_back(r.ns_per_body_step);
    if (ns.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::nth_element(ns.begin(), ns.begin() + ns.size() / 2, ns.end());
    return ns[ns.size() / 2];
}

// Cost ratios of the chosen run against the cheapest grid row that met the tolerance.
void compare_costs(const Problem& p, const Setup& s, const std::vector<Row>& grid, AutoCase& c,
                   physics::Integrator id) {
    const double chosen_model = physics::run_cost(s.model, id, c.steps);
    const double bodies = static_cast<double>(s.model.dynamic_bodies.size());
    const double chosen_measured = measured_ns(grid, p, c.integrator) * bodies * c.steps * 1e-9;
    double best_model = std::numeric_limits<double>::infinity(), best_measured = best_model;
    for (const Row& r : grid) {
        if (r.problem != p.name || r.diverged || r.max.orientation > c.tolerance ||
            r.max.position > c.tolerance)
            continue;
        const auto rid = physics::integrator_from_name(r.integrator);
        const double model = physics::run_cost(s.model, *rid, r.steps);
        if (model < best_model) {
            best_model = model;
            c.cheapest = r.integrator + " n=" + std::to_string(r.steps);
        }
        best_measured = std::min(best_measured, r.cost_s);
    }
    c.cost_ratio_model = chosen_model / best_model; // 0 when no row met it
    c.cost_ratio_measured = chosen_measured / best_measured;
    c.cost_within_2 = c.cost_ratio_model <= 2.0;
}

AutoCase run_case(const Problem& p, const Reference& ref, const std::vector<Row>& grid,
                  double tol) {
    AutoCase c;
    c.problem = p.name;
    c.tolerance = tol;
    const double base = p.duration / kSamples;
    const Setup s = make_setup(p, physics::Integrator::Rk4, base);
    const auto t0 = std::chrono::steady_clock::now();
    physics::PlanSettings settings;
    settings.stop = [] { return io::InterruptGuard::requested(); };
    physics::AccuracyPlan plan;
    try {
        plan = physics::plan_accuracy(s.model, s.state, base, kSamples, {tol, tol}, settings);
    } catch (const physics::Stopped&) {
        io::InterruptGuard::stop_if_requested("the study's pilot runs");
        throw;
    }
    c.pilot_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    c.pilots = static_cast<int>(plan.trials.size());
    c.found = plan.found;
    if (!plan.found) return c;
    c.integrator = std::string(physics::integrator_info(plan.integrator).name);
    c.steps = std::int64_t{kSamples} * plan.k;
    c.dt = plan.h;
    measure_choice(p, s, ref, c, plan.integrator, plan.k);
    c.ratio = c.estimate / c.truth;
    c.round_off = c.estimate < kRoundOff && c.truth < kRoundOff;
    c.within_3 = (c.ratio >= 1.0 / 3.0 && c.ratio <= 3.0) || c.round_off;
    c.meets = c.truth <= tol;
    compare_costs(p, s, grid, c, plan.integrator);
    return c;
}

} // namespace

std::vector<double> auto_tolerances() {
    return {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
}

std::vector<AutoCase> check_auto(const std::vector<Problem>& problems, const std::vector<Row>& grid,
                                 const std::vector<double>& tolerances, bool quick, int threads) {
    std::vector<const Problem*> checked;
    for (const Problem& p : problems)
        if (has_oracle(p)) checked.push_back(&p);
    std::vector<Reference> refs(checked.size());
    parallel_for(static_cast<int>(checked.size()), threads,
                 [&](int i) { refs[i] = make_reference(*checked[i], quick); });
    const int per = static_cast<int>(tolerances.size());
    std::vector<AutoCase> cases(checked.size() * tolerances.size());
    parallel_for(static_cast<int>(cases.size()), threads, [&](int i) {
        cases[i] = run_case(*checked[i / per], refs[i / per], grid, tolerances[i % per]);
    });
    return cases;
}

AutoSummary summarise(const std::vector<AutoCase>& cases) {
    AutoSummary s;
    for (const AutoCase& c : cases) {
        ++s.cases;
        if (!c.covered) continue;
        ++s.covered;
        s.within_3 += c.within_3;
        s.within_3_strict += c.ratio >= 1.0 / 3.0 && c.ratio <= 3.0;
        s.meets += c.meets;
        s.cost_within_2 += c.cost_within_2;
    }
    return s;
}

} // namespace tumble::app::study
