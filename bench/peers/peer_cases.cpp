#include "bench/peers/peer_cases.h"

#include "physics/scenes/contact_scenes.h"
#include "physics/scenes/sphere_rain.h"
#include "physics/scenes/state_hash.h"
#include "physics/step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace tumble::bench {
namespace {

using physics::State;
using physics::Vec3;

struct Case {
    std::string scene; // rain1000, rain8000, stack10
    std::string name;  // ode, tumble, tumble/threads:2, tumble/480x1, tumble/1440x3
    bool ode = false;
    int threads = 1;
    int substeps = 0, iterations = 0, relax = 0; // fixed settings; 0: the defaults
    double tolerance = 0;                        // m: world.contact_tolerance; 0: the default
};

struct Outcome {
    double seconds = 0; // CPU time (one thread) or wall clock (two threads)
    double wall = 0;
    double steps = 0;
    double penetration_mm = 0, drift_mm = 0, sink_mm = 0;
    double outside = 0, kinetic = 0, contacts = 0;
    double substeps_mean = 0, substeps_max = 0, sweeps_per_point = 0;
    std::uint64_t hash = 0;
};

double cpu_seconds() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

scenes::Scene make_scene(const std::string& name) {
    if (name == "rain1000") return scenes::sphere_rain(10, true);
    if (name == "rain8000") return scenes::sphere_rain(20, true);
    scenes::Scene s = scenes::box_stack(10, 0.2, 1.0 / 240.0);
    s.duration = 10.0;
    return s;
}

// The column of boxes: the largest sideways drift and sinking of any box since the start, and the
// deepest overlap at the end (bottom box into the floor, each box into the one below, measured
// along z: the column stays upright within a degree).
struct StackJudge {
    std::vector<Vec3> start;
    double drift = 0, sink = 0;
    void operator()(const State& s) {
        if (start.empty()) start = s.x;
        for (std::size_t i = 1; i < s.x.size(); ++i) {
            const Vec3 d = s.x[i] - start[i];
            drift = std::max(drift, d.head<2>().norm());
            sink = std::max(sink, -d.z());
        }
    }
    static double penetration(const State& s) {
        double worst = 0.1 - s.x[1].z();
        for (std::size_t i = 2; i < s.x.size(); ++i)
            worst = std::max(worst, 0.2 - (s.x[i].z() - s.x[i - 1].z()));
        return worst;
    }
};

void judge(const std::string& scene, const State& s, Outcome& o) {
    if (scene == "stack10") {
        o.penetration_mm = 1e3 * std::max(0.0, StackJudge::penetration(s));
        return;
    }
    const scenes::RainEnd end = scenes::judge_rain(s);
    o.penetration_mm = 1e3 * end.max_penetration;
    o.outside = end.outside;
    o.kinetic = end.kinetic_energy;
}

Outcome run_ode(const Case& c, const scenes::Scene& scene, OdeSpace space) {
    OdeWorld world(scene, space);
    const long steps = std::lround(scene.duration / scene.world.dt);
    State s;
    StackJudge stack;
    const bool watch = c.scene == "stack10";
    Outcome o;
    const double c0 = cpu_seconds(), w0 = wall_seconds();
    for (long k = 0; k < steps; ++k) {
        world.step();
        if (watch) world.fill(s), stack(s);
    }
    o.seconds = cpu_seconds() - c0;
    o.wall = wall_seconds() - w0;
    o.steps = static_cast<double>(steps);
    o.contacts = world.contacts();
    world.fill(s);
    judge(c.scene, s, o);
    o.drift_mm = 1e3 * stack.drift, o.sink_mm = 1e3 * stack.sink;
    return o;
}

Outcome run_tumble(const Case& c, scenes::Scene scene) {
    if (c.tolerance > 0) scene.world.contact.tolerance = c.tolerance;
    if (c.substeps > 0) {
        scene.world.contact.substeps = c.substeps;
        scene.world.contact.iterations = c.iterations;
        scene.world.contact.relax_iterations = c.relax;
    }
    const physics::Model model = physics::build_model(scene.world, scene.bodies);
    State s = physics::initial_state(model, scene.bodies);
    physics::StepWorkspace ws(c.threads);
    const long steps = std::lround(scene.duration / scene.world.dt);
    StackJudge stack;
    const bool watch = c.scene == "stack10";
    double body_substeps = 0, bodies = 0, point_sweeps = 0, points = 0, most = 0;
    Outcome o;
    const double c0 = cpu_seconds(), w0 = wall_seconds();
    for (long k = 0; k < steps; ++k) {
        physics::step(model, s, ws);
        const physics::ContactStats& st = ws.contacts.stats();
        body_substeps += st.effort.body_substeps;
        bodies += st.effort.bodies;
        point_sweeps += st.effort.point_sweeps;
        points += st.points;
        most = std::max(most, double(st.effort.substeps_max));
        if (watch) stack(s);
    }
    o.seconds = c.threads == 1 ? cpu_seconds() - c0 : wall_seconds() - w0;
    o.wall = wall_seconds() - w0;
    o.steps = static_cast<double>(steps);
    o.contacts = ws.contacts.stats().points;
    o.substeps_mean = bodies > 0 ? body_substeps / bodies : 0;
    o.substeps_max = most;
    o.sweeps_per_point = points > 0 ? point_sweeps / points : 0;
    o.hash = scenes::state_hash(s);
    judge(c.scene, s, o);
    o.drift_mm = 1e3 * stack.drift, o.sink_mm = 1e3 * stack.sink;
    return o;
}

std::vector<Case> cases_of(const std::string& scene, const std::vector<double>& tolerances) {
    std::vector<Case> out{{scene, "ode", true}, {scene, "tumble"}};
    for (const double tol : tolerances) {
        char name[48];
        std::snprintf(name, sizeof name, "tumble/tol:%gmm", 1e3 * tol);
        Case c{scene, name};
        c.tolerance = tol;
        out.push_back(c);
    }
    if (scene == "rain8000") out.push_back({scene, "tumble/threads:2", false, 2});
    out.push_back({scene, "tumble/480x1", false, 1, 2, 1, 1});
    if (scene != "rain8000") out.push_back({scene, "tumble/1440x3", false, 1, 6, 3, 2});
    return out;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

} // namespace

int run_peers(const Options& opt) {
    const std::vector<std::string> scenes{"rain1000", "rain8000", "stack10"};
    std::printf("load average at start: %s\n", load_average().c_str());
    std::string csv = "scene,case,steps_per_s,x_ode,max_penetration_mm,ode_penetration_mm,"
                      "drift_mm,sink_mm,outside,kinetic_energy_J,contacts_end,substeps_mean,"
                      "substeps_max,sweeps_per_point,speedup_2_threads,bit_identical\n";
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const std::string& name = scenes[k];
        if (!opt.only.empty() && ("," + opt.only + ",").find("," + name + ",") == std::string::npos)
            continue;
        const scenes::Scene scene = make_scene(name);
        const std::vector<Case> cases = cases_of(name, opt.tolerances);
        std::map<std::string, std::vector<Outcome>> runs;
        for (int rep = 0; rep < opt.reps[k]; ++rep)
            for (const Case& c : cases) {
                const Outcome o = c.ode ? run_ode(c, scene, opt.space) : run_tumble(c, scene);
                std::printf("  %s %-18s rep %d: %.1f steps/s, penetration %.3f mm\n", name.c_str(),
                            c.name.c_str(), rep, o.steps / o.seconds, o.penetration_mm);
                std::fflush(stdout);
                runs[c.name].push_back(o);
            }
        auto med = [&](const std::string& c, double Outcome::*f) {
            std::vector<double> v;
            for (const Outcome& o : runs[c]) v.push_back(o.*f);
            return median(v);
        };
        auto rate = [&](const std::string& c) {
            std::vector<double> v;
            for (const Outcome& o : runs[c]) v.push_back(o.steps / o.seconds);
            return median(v);
        };
        const double ode = rate("ode");
        std::printf("\n%s (medians of %d; ODE %.1f steps/s, max penetration %.3f mm)\n",
                    name.c_str(), opt.reps[k], ode, med("ode", &Outcome::penetration_mm));
        for (const Case& c : cases) {
            const double r = rate(c.name);
            std::string speedup, identical;
            if (c.threads == 2) {
                char b[32];
                std::snprintf(b, sizeof b, "%.2f",
                              med("tumble", &Outcome::wall) / med(c.name, &Outcome::wall));
                speedup = b;
                identical = runs[c.name].back().hash == runs["tumble"].back().hash ? "yes" : "NO";
            }
            char line[512];
            std::snprintf(
                line, sizeof line,
                "%s,%s,%.1f,%.2f,%.4f,%.4f,%.4f,%.4f,%.0f,%.4g,%.0f,%.2f,%.0f,%.2f,%s,%s\n",
                name.c_str(), c.name.c_str(), r, r / ode, med(c.name, &Outcome::penetration_mm),
                med("ode", &Outcome::penetration_mm), med(c.name, &Outcome::drift_mm),
                med(c.name, &Outcome::sink_mm), med(c.name, &Outcome::outside),
                med(c.name, &Outcome::kinetic), med(c.name, &Outcome::contacts),
                med(c.name, &Outcome::substeps_mean), med(c.name, &Outcome::substeps_max),
                med(c.name, &Outcome::sweeps_per_point), speedup.c_str(), identical.c_str());
            std::printf("  %s", line);
            csv += line;
        }
    }
    std::printf("\nload average at end: %s\n", load_average().c_str());
    std::printf("\nSummary:\n%s", csv.c_str());
    if (!opt.csv.empty()) std::ofstream(opt.csv) << csv;
    return 0;
}

} // namespace tumble::bench
