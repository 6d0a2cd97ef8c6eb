#include "app/study/contact_stability.h"
#include "app/study/boundary_search.h"
#include "app/study/runner.h"
#include "physics/build.h"
#include "physics/diagnostics.h"
#include "physics/integrator.h"
#include "physics/scenes/contact_scenes.h"
#include "physics/scenes/stability_scenes.h"
#include "physics/step.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::app::study {

using physics::Model;
using physics::State;
using physics::Vec3;

namespace {

constexpr double kDefaultDt = 1.0 / 240.0;
constexpr double kStackDrift = 1e-3; // m sideways
// A heavy cube settling onto a light one sinks into it by the soft contact's sag, F / (m_eff
// omega^2) with m_eff the light cube's (2.4 mm at 1:1000 and the default 1440 substeps per
// second), and sways sideways while it settles: 1.5 mm at 1:1000, then still. "Holds" for the
// mass-ratio stack is that sway within 5 mm (2.5% of the 20 cm edge), not the 1 mm that a stack
// of equal boxes is held to.
constexpr double kRatioDrift = 5e-3; // m sideways
constexpr double kStackSink = 1e-2;  // m down
constexpr double kTopDepth = 2e-3;   // m below the table
constexpr double kRestGain = 1e-9;   // of m g r

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

scenes::Scene scene_of(const ContactCase& c, double dt, int substeps) {
    if (c.family == "stack") {
        scenes::Scene s = scenes::box_stack(static_cast<int>(c.parameter), 0.2, dt);
        s.world.contact.substeps = substeps;
        s.duration = 10.0;
        return s;
    }
    if (c.family == "ratio") {
        scenes::Scene s = scenes::mass_ratio_stack(c.parameter, dt, substeps);
        s.duration = 10.0;
        return s;
    }
    if (c.family == "bullet") {
        scenes::Scene s = scenes::bullet(c.parameter, dt);
        s.world.contact.substeps = substeps;
        s.duration = 1.0 / c.parameter + 0.5; // reach the plate, then half a second more
        return s;
    }
    if (c.family == "top") return scenes::fast_top(c.parameter, dt, substeps);
    return scenes::resting_ball(dt, substeps);
}

// The measure of a case on one state (larger is worse); `start` is the initial state.
struct Measure {
    const ContactCase& c;
    const scenes::Scene& scene;
    const Model& model;
    const State& start;
    double start_energy; // diagnose(model, start).energy(), for "rest"

    double operator()(const State& s) const {
        if (c.family == "stack") return stack_drift(s, kStackDrift);
        if (c.family == "ratio") return stack_drift(s, kRatioDrift);
        if (c.family == "bullet") return s.x[1].x(); // the ball's centre; the plate is at x = 0
        if (c.family == "top") return top_depth(s);
        return physics::diagnose(model, s).energy() - start_energy;
    }
    // Sideways drift over kStackDrift, or sinking over kStackSink, as a multiple of its limit.
    double stack_drift(const State& s, double sideways) const {
        double worst = 0.0;
        for (int i = 1; i < model.body_count(); ++i) {
            const Vec3 d = s.x[i] - start.x[i];
            worst = std::max({worst, d.head<2>().norm() / sideways, -d.z() / kStackSink});
        }
        return worst;
    }
    double top_depth(const State& s) const {
        const physics::Pose p = physics::body_pose(model, s, 1);
        double lowest = std::numeric_limits<double>::infinity();
        for (const Vec3& v : scene.bodies[1].mesh->vertices)
            lowest = std::min(lowest, (p.position + p.orientation * v).z());
        return -lowest;
    }
};

double limit_of(const ContactCase& c, const Model& model) {
    if (c.family == "stack" || c.family == "ratio") return 1.0; // stack_drift is relative
    if (c.family == "bullet") return 0.0;
    if (c.family == "top") return kTopDepth;
    return kRestGain * model.mass[1] * 9.81 * 0.1;
}

} // namespace

std::vector<ContactCase> contact_cases() {
    std::vector<ContactCase> out;
    for (int n : {5, 10, 20})
        out.push_back({"stack", double(n), "stack " + number(n),
                       "no box moves over 1 mm sideways or 1 cm down in 10 s"});
    for (double r : {10.0, 100.0, 1000.0})
        out.push_back({"ratio", r, "ratio 1:" + number(r),
                       "heavy cube on a light one: 5 mm sideways, 1 cm down, 10 s"});
    for (double v : {1.0, 10.0, 50.0})
        out.push_back({"bullet", v, "bullet " + number(v) + " m/s",
                       "a 2 cm ball never crosses the mid-plane of a 1 cm plate"});
    for (double w : {100.0, 300.0, 1000.0})
        out.push_back({"top", w, "top " + number(w) + " rad/s",
                       "no point of the top more than 2 mm below the table in 10 s"});
    out.push_back({"rest", 0.0, "resting ball", "energy never above E0 + 1e-9 m g r in 10 s"});
    return out;
}

std::vector<int> contact_substep_settings(bool quick) {
    return quick ? std::vector<int>{0, 8} : std::vector<int>{0, 1, 4, 8};
}

ContactRun run_contact_case(const ContactCase& c, const std::string& integrator, double dt,
                            int substeps, int iterations, double tolerance) {
    scenes::Scene scene = scene_of(c, dt, substeps);
    scene.world.contact.iterations = iterations;
    scene.world.contact.tolerance = tolerance;
    scene.world.integrator = physics::integrator_from_name(integrator).value();
    const Model model = physics::build_model(scene.world, scene.bodies);
    State state = physics::initial_state(model, scene.bodies);
    const State start = state;
    const Measure measure{c, scene, model, start, physics::diagnose(model, start).energy()};
    const double limit = limit_of(c, model);
    ContactRun run;
    run.worst = -std::numeric_limits<double>::infinity();
    const auto steps = static_cast<long long>(std::ceil(scene.duration / dt - 1e-9));
    try {
        for (long long k = 0; k < steps; ++k) {
            physics::step(model, state);
            run.worst = std::max(run.worst, measure(state));
            if (run.worst > limit) return run; // failed: no need to run on
        }
    } catch (const physics::DivergenceError&) {
        run.diverged = true;
        run.worst = std::numeric_limits<double>::infinity();
        return run;
    }
    run.held = true;
    return run;
}

namespace {

ContactStabilityResult search(const ContactCase& c, const std::string& integrator, int substeps,
                              double ratio) {
    ContactStabilityResult r{c, integrator, substeps};
    const Boundary b =
        largest_passing(kDefaultDt, kMinContactDt, kMaxContactDt, ratio, [&](double dt) {
            ++r.evaluations;
            return run_contact_case(c, integrator, dt, substeps).held;
        });
    r.dt = b.value;
    r.holds_default = b.holds_start;
    r.below_range = b.below_range;
    r.above_range = b.above_range;
    return r;
}

} // namespace

std::vector<ContactStabilityResult> contact_stability_map(bool quick, int threads) {
    const std::vector<ContactCase> cases = contact_cases();
    std::vector<std::string> names;
    if (quick) {
        names = {"rk4", "symplectic_euler"};
    } else {
        for (const physics::IntegratorInfo& info : physics::integrators())
            names.emplace_back(info.name);
    }
    const std::vector<int> subs = contact_substep_settings(quick);
    const int per_case = static_cast<int>(names.size() * subs.size());
    std::vector<ContactStabilityResult> out(cases.size() * per_case);
    parallel_for(static_cast<int>(out.size()), threads, [&](int i) {
        const int j = i % per_case;
        out[i] = search(cases[i / per_case], names[j / subs.size()], subs[j % subs.size()],
                        quick ? 1.25 : 1.05);
    });
    return out;
}

} // namespace tumble::app::study
