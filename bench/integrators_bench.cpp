// Cost of a step per body for every named integrator, and what "model only what a scene requires"
// saves. Run with repetitions and keep the CSV (scripts/bench-integrators.sh does both):
//
//   books/<integrator>            1000 torque-free books tumbling near their middle axis (the body
//                                 of scenes::intermediate_axis_scene): each integrator's full work.
//                                 Counters: ns_per_body_step, and the accuracy of one run of the
//                                 intermediate-axis scene at h = 1/240 s over 10 s against the
//                                 exact solution (computed once, not timed): energy_err
//                                 (max |E/E0 - 1|), momentum_err (max |L - L0| / |L0|),
//                                 orientation_err (rad, at 10 s).
//   spheres/<integrator>/assembled  1000 torque-free spheres without gravity: the step as the scene
//   spheres/<integrator>/full       needs it (no gravity, no loads, no gyroscopic work, no contact
//                                 stage: they fly apart and cannot touch) and with
//                                 force_all_passes() (every pass, no isotropic shortcut, and since
//                                 the contacts commit the contact stage too, which finds nothing:
//                                 same results, plus its cost; results/vm/ before 2026-11-22
//                                 predate this).
//
// Each iteration restores a saved state and takes 100 steps (MuJoCo's step benchmark habit), so
// every repetition times the same motion. After the runs a summary table gives the medians with
// two ratios measured in the same run: each integrator's cost over symplectic_euler's (the
// cheapest method that rotates exactly), and the full pipeline's cost over the assembled step's.
// `--summary=FILE` also writes that table as CSV.
#include "bench/median_reporter.h"
#include "physics/build.h"
#include "physics/diagnostics.h"
#include "physics/exact/body_motion.h"
#include "physics/integrator.h"
#include "physics/passes.h"
#include "physics/scenes/reference_scenes.h"
#include "physics/step.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace tumble::physics {
namespace {

constexpr int kBodies = 1000;
constexpr int kStepsPerIteration = 100;

struct World {
    Model model;
    State state;
};

World build(const scenes::Scene& scene, Integrator integrator, double h) {
    WorldDef w = scene.world;
    w.integrator = integrator;
    w.dt = h;
    World out{build_model(w, scene.bodies), {}};
    out.state = initial_state(out.model, scene.bodies);
    return out;
}

// 1000 copies of the intermediate-axis book, each with a slightly different spin and orientation.
scenes::Scene books() {
    const scenes::Scene one = scenes::intermediate_axis_scene();
    scenes::Scene scene = one;
    scene.bodies.clear();
    for (int i = 0; i < kBodies; ++i) {
        BodyDef b = one.bodies[0];
        const double a = 0.01 * i;
        b.position = Vec3(0.5 * (i % 40), 0.5 * (i / 40), 1.0);
        b.orientation =
            Quat(Eigen::AngleAxisd(a, Vec3(std::cos(a), std::sin(a), 1.0).normalized()));
        b.angular_velocity = b.orientation * Vec3(6.0 + 0.001 * i, 0.05, 0.05 - 0.0001 * i);
        scene.bodies.push_back(b);
    }
    return scene;
}

void time_steps(benchmark::State& bench, World& w) {
    for (int k = 0; k < 240; ++k) step(w.model, w.state); // warm up: one second of motion
    const State saved = w.state;
    for (auto _ : bench) {
        w.state = saved; // same capacity: no allocation
        for (int k = 0; k < kStepsPerIteration; ++k) step(w.model, w.state);
        benchmark::DoNotOptimize(w.state.q.data());
    }
    // Invert(rate of 1e-9 body-steps per second) = nanoseconds per body-step.
    const double body_steps = static_cast<double>(kStepsPerIteration) * kBodies;
    bench.counters["ns_per_body_step"] =
        benchmark::Counter(body_steps * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                  benchmark::Counter::kInvert);
}

struct Accuracy {
    double energy = 0.0, momentum = 0.0, orientation = 0.0;
};

// The intermediate-axis scene at the default step 1/240 s for 10 s (2.7 flips), against the
// exact Jacobi solution.
Accuracy accuracy(Integrator integrator) {
    World w = build(scenes::intermediate_axis_scene(), integrator, 1.0 / 240.0);
    const exact::ExactBodyMotion exact_motion(w.model, w.state, 0);
    const Diagnostics d0 = diagnose(w.model, w.state);
    Accuracy a;
    for (int k = 0; k < 2400; ++k) {
        step(w.model, w.state);
        const Diagnostics d = diagnose(w.model, w.state);
        a.energy = std::max(a.energy, std::abs(d.energy() / d0.energy() - 1.0));
        a.momentum = std::max(a.momentum, (d.angular_momentum - d0.angular_momentum).norm() /
                                              d0.angular_momentum.norm());
    }
    a.orientation = rotation_angle_between(w.state.q[0], exact_motion.at(10.0).q);
    return a;
}

void bench_books(benchmark::State& bench, Integrator integrator) {
    World w = build(books(), integrator, 1.0 / 240.0);
    time_steps(bench, w);
    const Accuracy a = accuracy(integrator);
    bench.counters["energy_err"] = a.energy;
    bench.counters["momentum_err"] = a.momentum;
    bench.counters["orientation_err"] = a.orientation;
}

void bench_spheres(benchmark::State& bench, Integrator integrator, bool full) {
    World w = build(scenes::torque_free_spheres(kBodies), integrator, 1.0 / 240.0);
    if (full) force_all_passes(w.model);
    time_steps(bench, w);
}

// Keeps the medians (or the single runs, without repetitions) and prints the summary at the end.
class SummaryReporter : public bench::MedianReporter {
  public:
    using MedianReporter::MedianReporter;

    void Finalize() override {
        ConsoleReporter::Finalize();
        const double base = value("books/symplectic_euler", "ns_per_body_step");
        std::string csv = "integrator,order,ns_per_body_step,ratio_to_symplectic_euler,energy_err,"
                          "momentum_err,orientation_err,spheres_assembled_ns,spheres_full_ns,"
                          "full_over_assembled\n";
        for (const IntegratorInfo& info : integrators()) {
            const std::string n(info.name);
            const double ns = value("books/" + n, "ns_per_body_step");
            const double sa = value("spheres/" + n + "/assembled", "ns_per_body_step");
            const double sf = value("spheres/" + n + "/full", "ns_per_body_step");
            char line[512];
            std::snprintf(line, sizeof line, "%s,%d,%.2f,%.2f,%.3g,%.3g,%.3g,%.2f,%.2f,%.2f\n",
                          n.c_str(), info.order, ns, ns / base, value("books/" + n, "energy_err"),
                          value("books/" + n, "momentum_err"),
                          value("books/" + n, "orientation_err"), sa, sf, sf / sa);
            csv += line;
        }
        std::printf("\nSummary (%s; ns per body-step, ratios measured in this run):\n%s",
                    any_median() ? "medians" : "single runs, no repetitions", csv.c_str());
        if (!path_.empty()) std::ofstream(path_) << csv;
    }

  private:
};

} // namespace
} // namespace tumble::physics

int main(int argc, char** argv) {
    using namespace tumble::physics;
    std::string summary;
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--summary=", 10) == 0)
            summary = argv[i] + 10;
        else
            argv[kept++] = argv[i];
    }
    argc = kept;
    for (const IntegratorInfo& info : integrators()) {
        const std::string n(info.name);
        benchmark::RegisterBenchmark(("books/" + n).c_str(), bench_books, info.id)
            ->Unit(benchmark::kMicrosecond);
        for (bool full : {false, true})
            benchmark::RegisterBenchmark(("spheres/" + n + (full ? "/full" : "/assembled")).c_str(),
                                         bench_spheres, info.id, full)
                ->Unit(benchmark::kMicrosecond);
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    SummaryReporter reporter(summary);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
