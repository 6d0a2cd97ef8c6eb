// The sphere-rain benchmark of issue 4 (scene: physics/scenes/sphere_rain.h). Run with
// scripts/bench-sphere-rain.sh, which keeps the CSV under bench/results/<machine>/:
//
//   rain/<N>/shifted/threads:1   the benchmark: N = 1000 and 8000 spheres, the whole 5 s
//                                (1200 steps) from the initial grid, one thread
//   rain/<N>/shifted/threads:2   the same on two threads; its final state must have the bits of
//                                the single-threaded run (hash compared, reported as identical)
//   rain/<N>/columns/threads:1   the unshifted scene: the spheres stack in columns
//   rain/<N>/shifted_480x1/threads:1  the baseline in the same run: the solver settings before
//                                issue 13 (480 substeps per second, one solve and one relax
//                                sweep each), which let
//                                stacks rock; the summary gives the defaults' cost against it
//   free_flight/assembled        issue 4's "a scene with no contacts runs none of it": the two
//   free_flight/contacts_forced  bodies of scenes::gravity_spin_scene (cannot touch, so no contact
//                                stage) against the same scene with the stage forced on
//
// Each repetition builds the scene (not timed) and times every step of the run: one thread by
// its CPU time (the machine is shared: a preempted thread does not count waiting time), two
// threads by the wall clock; the 2-core speed-up compares the wall-clock times of both. Counters
// per run: steps_per_s, us_per_body_step, us_per_contact (time over the sum of contact points over
// the steps), us_per_contact_iteration (per point and solver sweep: each point's solve and relax
// sweeps over its island's substeps, ContactEffort::point_sweeps), and at the end: contacts
// (points), manifolds, max_penetration_mm, kinetic_energy_J, outside (spheres outside the box or
// below the floor). The summary gives the medians, the 2-core speed-up and the targets of the
// issue, each ratio from this run.
#include "physics/scenes/reference_scenes.h"
#include "physics/scenes/sphere_rain.h"
#include "physics/scenes/state_hash.h"
#include "physics/step.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>

namespace tumble::bench {
namespace {

using physics::Model;
using physics::State;
using physics::StepWorkspace;
using scenes::RainEnd;
using scenes::state_hash;

constexpr int kRainSteps = 1200; // 5 s at 1/240 s

// Final-state hashes of the single-threaded runs, by N: the 2-thread runs must match them.
std::map<int, std::uint64_t> g_single_hash;

void bench_rain(benchmark::State& bench, int n, bool shifted, int threads, bool legacy) {
    const int count = n * n * n;
    StepWorkspace ws(threads);
    double body_steps = 0, point_steps = 0, sweeps = 0;
    double stage[7] = {}; // ms summed over the steps: the stage's ContactProfile
    RainEnd end;
    physics::ContactStats last;
    std::uint64_t hash = 0;
    for (auto _ : bench) {
        bench.PauseTiming();
        scenes::Scene scene = scenes::sphere_rain(n, shifted);
        if (legacy) {
            scene.world.contact.substeps = 2;
            scene.world.contact.iterations = 1;
            scene.world.contact.relax_iterations = 1;
        }
        const Model model = build_model(scene.world, scene.bodies);
        State state = initial_state(model, scene.bodies);
        bench.ResumeTiming();
        for (int k = 0; k < kRainSteps; ++k) {
            step(model, state, ws);
            const physics::ContactStats& st = ws.contacts.stats();
            const physics::ContactProfile& pr = ws.contacts.profile();
            stage[0] += pr.broad, stage[1] += pr.narrow, stage[2] += pr.prepare;
            stage[3] += pr.impacts, stage[4] += pr.solve, stage[5] += pr.integrate;
            stage[6] += pr.finish;
            point_steps += st.points;
            sweeps += st.effort.point_sweeps; // every point's sweeps, over its island's substeps
        }
        bench.PauseTiming();
        body_steps += static_cast<double>(kRainSteps) * count;
        last = ws.contacts.stats();
        end = scenes::judge_rain(state);
        hash = state_hash(state);
        bench.ResumeTiming();
    }
    if (threads == 1 && shifted && !legacy) g_single_hash[count] = hash;
    const auto inverted = benchmark::Counter::kIsRate | benchmark::Counter::kInvert;
    bench.counters["steps_per_s"] = benchmark::Counter(
        static_cast<double>(kRainSteps) * bench.iterations(), benchmark::Counter::kIsRate);
    bench.counters["us_per_body_step"] = benchmark::Counter(body_steps * 1e-6, inverted);
    bench.counters["us_per_contact"] = benchmark::Counter(point_steps * 1e-6, inverted);
    bench.counters["us_per_contact_iteration"] = benchmark::Counter(sweeps * 1e-6, inverted);
    // Share of the stepping time spent in each stage, %.
    const char* stage_names[7] = {"broad", "narrow",    "prepare", "impacts",
                                  "solve", "integrate", "finish"};
    double total = 0;
    for (double t : stage) total += t;
    for (int k = 0; k < 7; ++k)
        bench.counters[std::string("pct_") + stage_names[k]] = 100.0 * stage[k] / total;
    bench.counters["contacts"] = last.points;
    bench.counters["manifolds"] = last.manifolds;
    bench.counters["workers"] = last.workers;
    bench.counters["max_penetration_mm"] = 1e3 * end.max_penetration;
    bench.counters["kinetic_energy_J"] = end.kinetic_energy;
    bench.counters["outside"] = end.outside;
    if (threads > 1 && shifted) {
        const auto single = g_single_hash.find(count);
        bench.counters["identical"] =
            single == g_single_hash.end() ? -1.0 : double(single->second == hash);
    }
}

void bench_free_flight(benchmark::State& bench, bool forced) {
    const scenes::Scene scene = scenes::gravity_spin_scene();
    Model model = build_model(scene.world, scene.bodies);
    if (model.passes.contacts) bench.SkipWithError(("can touch: " + model.touch.why).c_str());
    model.passes.contacts = forced;
    const State saved = initial_state(model, scene.bodies);
    State state = saved;
    StepWorkspace ws(1);
    constexpr int kSteps = 1000;
    for (auto _ : bench) {
        state = saved;
        for (int k = 0; k < kSteps; ++k) step(model, state, ws);
        benchmark::DoNotOptimize(state.x.data());
    }
    const double body_steps = static_cast<double>(kSteps) * model.dynamic_bodies.size();
    bench.counters["ns_per_body_step"] =
        benchmark::Counter(body_steps * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                  benchmark::Counter::kInvert);
}

} // namespace
} // namespace tumble::bench

#include "bench/sphere_rain_summary.h"

int main(int argc, char** argv) {
    using namespace tumble::bench;
    std::string summary;
    int reps_small = 5, reps_large = 3;
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--summary=", 10) == 0)
            summary = argv[i] + 10;
        else if (std::strncmp(argv[i], "--reps1000=", 11) == 0)
            reps_small = std::atoi(argv[i] + 11);
        else if (std::strncmp(argv[i], "--reps8000=", 11) == 0)
            reps_large = std::atoi(argv[i] + 11);
        else
            argv[kept++] = argv[i];
    }
    argc = kept;
    for (const int n : {10, 20}) {
        const int reps = n == 10 ? reps_small : reps_large;
        const std::string base = "rain/" + std::to_string(n * n * n);
        for (const auto& [name, shifted, threads, legacy] :
             {std::tuple{"/shifted/threads:1", true, 1, false},
              std::tuple{"/shifted/threads:2", true, 2, false},
              std::tuple{"/columns/threads:1", false, 1, false},
              std::tuple{"/shifted_480x1/threads:1", true, 1, true}}) {
            benchmark::internal::Benchmark* b = benchmark::RegisterBenchmark(
                (base + name).c_str(), bench_rain, n, shifted, threads, legacy);
            b->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(reps);
            if (threads > 1) b->UseRealTime();
        }
    }
    for (const bool forced : {false, true})
        benchmark::RegisterBenchmark(forced ? "free_flight/contacts_forced"
                                            : "free_flight/assembled",
                                     bench_free_flight, forced)
            ->Unit(benchmark::kMicrosecond)
            ->Repetitions(5);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    RainSummary reporter(summary);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
