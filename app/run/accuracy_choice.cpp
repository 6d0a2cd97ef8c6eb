// world.integrator "auto" resolved before a run, and the run's account of it (accuracy_choice.h).
#include "app/run/accuracy_choice.h"

#include "app/run/simulation.h"
#include "app/scene/scene_error.h"
#include "io/interrupt.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace tumble::app {
namespace {

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string tolerance_text(const physics::Tolerance& t) {
    return fmt("%.3g rad", t.rotation) + " / " + fmt("%.3g m", t.position);
}

std::string name_of(physics::Integrator id) {
    return std::string(physics::integrator_info(id).name);
}

std::string steps_text(int k) {
    return std::to_string(k) + (k == 1 ? " step" : " steps") + " per frame";
}

// One pilot: "rk4, 4 steps per frame: estimated 0.31 of the tolerance, cost 1.2e+05 (accepted)".
std::string trial_text(const physics::PlanTrial& t) {
    std::string s = name_of(t.integrator) + ", " + steps_text(t.k) + ": ";
    s += t.diverged ? std::string("diverged")
                    : "estimated " + fmt("%.2g", t.error) + " x the tolerance";
    s += ", cost " + fmt("%.3g", t.cost);
    if (t.accepted) s += " (meets it)";
    return s;
}

} // namespace

void resolve_auto_integrator(Scene& scene) {
    if (!scene.accuracy.auto_integrator || scene.accuracy.plan) return;
    const physics::Tolerance tol = *scene.accuracy.tolerance;
    const int fps = scene.render.fps;
    const std::int64_t frames = std::max<std::int64_t>(1, std::llround(scene.duration * fps));
    const double base = 1.0 / fps;
    const Simulation start = make_simulation(scene, base);
    const auto t0 = std::chrono::steady_clock::now();
    // With contacts, never a longer step than the scene's own: the contacts' behaviour (bounces,
    // stacking) is set by it, and the estimate, which stops at a contact, cannot judge it.
    physics::PlanSettings settings;
    if (start.model.passes.contacts)
        settings.min_k = std::max(1, static_cast<int>(std::ceil(base / scene.world.dt - 1e-9)));
    settings.stop = [] { return io::InterruptGuard::requested(); };
    physics::AccuracyPlan plan;
    try {
        plan = physics::plan_accuracy(start.model, start.state, base, frames, tol, settings);
    } catch (const physics::Stopped&) {
        io::InterruptGuard::stop_if_requested("auto's pilot runs");
        throw;
    }
    scene.accuracy.pilot_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!plan.found) {
        std::string pilots;
        for (const physics::PlanTrial& t : plan.trials) pilots += "; " + trial_text(t);
        throw SceneError(scene.source, scene.accuracy.tolerance_place,
                         "no integrator meets the tolerance " + tolerance_text(tol) +
                             " with at most " + std::to_string(physics::PlanSettings{}.max_k) +
                             " steps per frame (pilots" + pilots + ")");
    }
    scene.world.integrator = plan.integrator;
    scene.world.dt = 1.0 / (static_cast<double>(fps) * plan.k);
    scene.accuracy.plan = std::move(plan);
}

std::vector<std::string> describe_choice(const Scene& scene, bool brief) {
    std::vector<std::string> out;
    if (!scene.accuracy.plan) return out;
    const physics::AccuracyPlan& p = *scene.accuracy.plan;
    out.push_back("auto: " + name_of(p.integrator) + " at h = " + fmt("%.6g s", p.h) + " (" +
                  steps_text(p.k) + ") meets " + tolerance_text(*scene.accuracy.tolerance) +
                  " over " + fmt("%g s", scene.duration) + ": estimated error " +
                  fmt("%.2g", p.error) + " x the tolerance; the cheapest of " +
                  std::to_string(p.trials.size()) + " pilot runs (" +
                  fmt("%.2f s", scene.accuracy.pilot_seconds) + ")");
    if (brief) return out;
    out.push_back("  why: each pilot runs the whole duration with the step-doubling estimate; the "
                  "next step comes from the integrator's order (E ~ h^p); pilots that would cost "
                  "more than the best plan so far are not run. Cost = steps x the integrator's "
                  "cost per body-step (docs/integrators.md).");
    for (const std::string& s : p.skipped) out.push_back("  skipped " + s);
    for (const physics::PlanTrial& t : p.trials) out.push_back("  pilot " + trial_text(t));
    for (const physics::BodyEstimate& b : p.estimate)
        if (!b.holds())
            out.push_back("  not covered: body " + std::to_string(b.body) +
                          " after t = " + fmt("%.4g s", b.valid_until) + " (" +
                          physics::estimate_limit_name(b.limit) +
                          "): the estimate, and so the tolerance, hold only before");
    return out;
}

ToleranceCheck check_tolerance(const physics::Tolerance& tol,
                               const std::vector<physics::BodyEstimate>& estimate,
                               const std::vector<std::string>& body_names) {
    ToleranceCheck r;
    double worst = 0.0;
    for (const physics::BodyEstimate& b : estimate) {
        const std::string name =
            "body " + std::to_string(b.body) +
            (b.body < static_cast<int>(body_names.size()) && !body_names[b.body].empty()
                 ? " \"" + body_names[b.body] + "\""
                 : std::string{});
        worst = std::max(worst, physics::normalised_error(b.max, tol));
        if (b.max.rotation > tol.rotation || b.max.position > tol.position) {
            r.met = false;
            r.lines.push_back(
                "warning: " + name + ": estimated error " + fmt("%.2g rad", b.max.rotation) + ", " +
                fmt("%.2g m", b.max.position) + " exceeds the tolerance " + tolerance_text(tol));
        }
        if (!b.holds())
            r.lines.push_back(
                name + ": the estimate holds only until t = " + fmt("%.4g s", b.valid_until) +
                " (" + physics::estimate_limit_name(b.limit) + ")");
    }
    if (r.met)
        r.lines.insert(r.lines.begin(), "tolerance " + tolerance_text(tol) +
                                            " met: largest estimated error " + fmt("%.2g", worst) +
                                            " x the tolerance");
    return r;
}

void report_tolerance(const Scene& scene, const Simulation& sim) {
    if (!scene.accuracy.tolerance || !sim.estimate.estimator) return;
    const auto bodies = sim.estimate.estimator->bodies();
    const ToleranceCheck c =
        check_tolerance(*scene.accuracy.tolerance, {bodies.begin(), bodies.end()}, sim.body_names);
    for (const std::string& line : c.lines) std::fprintf(stderr, "tumble: %s\n", line.c_str());
}

} // namespace tumble::app
