// `tumble explain`: prints the model that will run: bodies, loads, integrator, and which stages of
// the step are on and why, contacts included ("model only what a scene requires").
#include "app/cli/failure.h"
#include "app/cli/scene_options.h"
#include "app/cli/subcommand.h"
#include "app/run/accuracy_choice.h"
#include "app/run/prepare_run.h"
#include "app/study/contact_check.h"
#include "io/interrupt.h"
#include "physics/error_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace tumble::app {
namespace {

void print_bodies(const Scene& scene, const physics::Model& m) {
    std::printf("bodies (%d, %zu dynamic):\n", m.body_count(), m.dynamic_bodies.size());
    for (int i = 0; i < m.body_count(); ++i) {
        const physics::Vec3& I = m.inertia[i];
        std::printf("  %3d %-16s %-6s", i, scene.looks[i].name.c_str(),
                    physics::shape_name(m.shape[i].kind));
        if (!m.is_dynamic(i)) {
            std::printf(" static\n");
            continue;
        }
        std::printf(" m = %.6g kg, I = (%.6g, %.6g, %.6g) kg m^2%s, gravity x%.3g\n", m.mass[i],
                    I.x(), I.y(), I.z(), m.isotropic[i] ? " isotropic" : "", m.gravity_scale[i]);
    }
}

// How many dynamic bodies need each pass (the reason a pass is on, in numbers).
struct PassCounts {
    int dynamic = 0, gravity = 0, loaded = 0, anisotropic = 0;
};

PassCounts count_passes(const physics::Model& m) {
    PassCounts c;
    for (int i : m.dynamic_bodies) {
        ++c.dynamic;
        c.gravity += m.gravity_scale[i] != 0.0 && m.gravity != physics::Vec3::Zero();
        c.loaded += m.applied_force[i] != physics::Vec3::Zero() ||
                    m.applied_torque[i] != physics::Vec3::Zero();
        c.anisotropic += !m.isotropic[i];
    }
    return c;
}

// The contact stage and its reason (physics/can_touch.h), its substeps and sleeping.
void print_contacts(const physics::Model& m) {
    const physics::TouchReport& t = m.touch;
    if (!m.passes.contacts) {
        std::printf("  contacts       off: %s\n", t.why.c_str());
        return;
    }
    int shapes = 0;
    for (int i = 0; i < m.body_count(); ++i) shapes += !m.is_dynamic(i);
    std::printf("  contacts       on: %s (first of %lld pairs checked); %d bodies collide "
                "(%d static, %zu dynamic); ",
                t.why.c_str(), t.pairs_checked, m.body_count(), shapes, m.dynamic_bodies.size());
    if (physics::fixed_effort(m.contact)) {
        const int substeps = physics::substep_count(m.contact, m.dt);
        std::printf("effort fixed by the scene: %d substep%s of %.3g ms per step, %d solve and "
                    "%d relax sweeps each; ",
                    substeps, substeps == 1 ? "" : "s", 1e3 * m.dt / substeps,
                    physics::iteration_count(m.contact), m.contact.relax_iterations);
    } else {
        std::printf("effort on demand: each island of bodies in contact gets the substeps that "
                    "keep its contacts' sag within the contact tolerance %.3g mm and its turn "
                    "within 0.1 rad per substep, and 1-3 solve and 1-2 relax sweeps each "
                    "(docs/contacts.md); ",
                    1e3 * m.contact.tolerance);
    }
    if (m.contact.sleeping)
        std::printf("sleeping on (bodies slower than %g m/s for %g s stop)\n",
                    m.contact.sleep_speed, m.contact.time_to_sleep);
    else
        std::printf("sleeping off\n");
}

void print_passes(const physics::Model& m) {
    const physics::Passes& p = m.passes;
    const PassCounts c = count_passes(m);
    std::printf("step stages:\n");
    if (p.gravity)
        std::printf("  gravity        on: %d of %d dynamic bodies feel g * gravity_scale != 0\n",
                    c.gravity, c.dynamic);
    else
        std::printf("  gravity        off: g = 0 or every gravity_scale is 0 (no gravity work)\n");
    if (p.applied_loads)
        std::printf("  applied loads  on: %d of %d dynamic bodies have a force or torque\n",
                    c.loaded, c.dynamic);
    else
        std::printf("  applied loads  off: no body has an applied force or torque%s\n",
                    p.gravity ? "" : " (no velocity kicks at all)");
    if (p.dampers)
        std::printf("  dampers        on: %zu viscous damper%s between bodies, after each step "
                    "(physics/damper.h)\n",
                    m.dampers.size(), m.dampers.size() == 1 ? "" : "s");
    if (p.gyroscopic)
        std::printf("  gyroscopic     on: %d of %d dynamic bodies have unequal moments%s\n",
                    c.anisotropic, c.dynamic,
                    c.anisotropic < c.dynamic ? " (the isotropic skip it: w x I w = 0)" : "");
    else
        std::printf("  gyroscopic     off: every dynamic body is isotropic (w x I w = 0)\n");
    print_contacts(m);
    const physics::IntegratorInfo& info = physics::integrator_info(m.integrator);
    const std::string order = info.order == physics::kExactOrder
                                  ? "exact: no truncation error"
                                  : "order " + physics::order_text(info.order);
    std::printf("  integrate      %s (%s): %s\n", std::string(info.name).c_str(), order.c_str(),
                std::string(info.summary).c_str());
    std::printf(
        "  check finite   on: a NaN or infinite state stops the run naming body and step\n");
}

// world.error_estimate or --error-estimate (physics/error_estimate.h), when on.
void print_error_estimate(const Scene& scene, const physics::Model& m) {
    const ErrorEstimateSettings& e = scene.error_estimate;
    if (!e.on) return;
    const physics::IntegratorInfo& info = physics::integrator_info(m.integrator);
    std::printf("error estimate: on: step doubling, a shadow run at h/2 = %.6g s beside the run "
                "(%s, order %d: e = (y_h - y_h/2) x %.4g), per moving body in rad and m, at the "
                "end",
                0.5 * m.dt, std::string(info.name).c_str(), info.order,
                physics::richardson_factor(info.order));
    for (std::size_t i = 0; i < e.times.size(); ++i)
        std::printf("%s%g", i == 0 ? ", at t = " : ", ", e.times[i]);
    std::printf("%s and its maximum; about 2x more stepping%s\n", e.times.empty() ? "" : " s",
                m.passes.contacts ? "; a body's estimate stops at its first contact or sleep" : "");
}

// The effort the contact solver spends on this scene, counted over a pilot run of its first second
// (or the whole run if shorter): effort on demand is decided while the scene runs.
void print_effort(const Scene& scene, const Timeline& tl) {
    Simulation pilot = make_simulation(scene, tl.h);
    if (!pilot.model.passes.contacts) return;
    const double seconds = std::min(1.0, scene.duration);
    const auto steps = static_cast<long long>(std::ceil(seconds / tl.h - 1e-9));
    for (long long k = 0; k < steps; ++k) pilot.step();
    std::printf("contact effort, counted over the first %.3g s (%lld steps): %s\n", seconds, steps,
                effort_summary(pilot).c_str());
}

// The contact stability map's cases this scene resembles, each run at the scene's settings
// (app/study/contact_check.h); a case that fails is a warning.
void print_contact_checks(const physics::Model& m, const physics::State& s) {
    const std::vector<study::ContactCheck> checks = study::check_contact_regions(m, s);
    if (checks.empty()) return;
    std::printf("contact stability map (tumble study; docs/contacts.md), at this scene's step and "
                "substeps:\n");
    for (const study::ContactCheck& c : checks) {
        if (c.run.held) {
            std::printf("  %-16s holds: %s (%s)\n", c.c.label.c_str(), c.c.bound.c_str(),
                        c.resemblance.c_str());
            continue;
        }
        std::printf("  %-16s warning: fails%s: %s; the scene has %s. See the contact map of "
                    "`tumble study` for the steps, substeps and iterations that hold\n",
                    c.c.label.c_str(), c.run.diverged ? " (diverged)" : "", c.c.bound.c_str(),
                    c.resemblance.c_str());
        std::fprintf(stderr,
                     "tumble: warning: %s: %s: outside the contact stability map's "
                     "region at this step (%s)\n",
                     c.c.label.c_str(), c.resemblance.c_str(), c.c.bound.c_str());
    }
}

int run_explain(const SceneOptions& opts) {
    io::InterruptGuard guard; // auto's pilot runs stop on Ctrl-C
    const PreparedRun run = prepare_run(load_for_command(opts), {1, false});
    const Scene& scene = run.scene;
    const Timeline& tl = run.timeline;
    const Simulation& sim = run.sim;
    std::printf("scene: %s%s%s\n", scene.source.c_str(), scene.title.empty() ? "" : " - ",
                scene.title.c_str());
    const physics::Vec3& g = sim.model.gravity;
    std::printf("world: gravity (%g, %g, %g) m/s^2, duration %g s\n", g.x(), g.y(), g.z(),
                scene.duration);
    std::printf("time: %s\n", tl.describe().c_str());
    print_bodies(scene, sim.model);
    print_passes(sim.model);
    for (const std::string& line : describe_choice(scene, false)) std::printf("%s\n", line.c_str());
    if (scene.accuracy.tolerance && !scene.accuracy.plan)
        std::printf("tolerance: %.3g rad / %.3g m, checked after the run by the error estimate "
                    "(the integrator is the scene's; \"auto\" would choose one)\n",
                    scene.accuracy.tolerance->rotation, scene.accuracy.tolerance->position);
    print_error_estimate(scene, sim.model);
    print_effort(scene, tl);
    print_contact_checks(sim.model, sim.state);
    return kOk;
}

} // namespace

Subcommand add_explain_command(CLI::App& app) {
    auto opts = std::make_shared<SceneOptions>();
    CLI::App* e =
        app.add_subcommand("explain", "print the model that will run and which stages are on");
    add_scene_options(e, *opts);
    add_error_estimate_options(e, *opts);
    return {[e] { return e->parsed(); }, [opts] { return run_explain(*opts); }};
}

} // namespace tumble::app
