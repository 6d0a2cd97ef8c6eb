#pragma once
// Runs the study's grid: for every problem, integrator and step count one accuracy run (errors at
// the sample times against the reference) and one timing run (the stepping loop alone, repeated,
// timed by the thread's CPU clock so that other processes on the machine do not inflate it).
// Work is shared by `threads` workers, one row at a time; every row is computed by one thread from
// its own model and state, so the errors do not depend on the thread count (only the timings do).
#include "app/study/study.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace tumble::app::study {

struct TimingSettings {
    int repetitions = 5;           // the median of this many repetitions is reported
    double min_rep_seconds = 2e-3; // a repetition repeats the run until it lasts at least this
};

// This thread's CPU time, s. The timing runs read it, not the wall clock: a step's cost is the work
// it does, and on a shared machine (other builds, other workers of the study) the wall clock also
// counts the time the thread was not running.
double thread_seconds();

// Calls fn(i) for i in [0, count) on `threads` threads (the calling thread is one of them).
// Exceptions are rethrown on the calling thread after every worker stopped.
void parallel_for(int count, int threads, const std::function<void(int)>& fn);

// The pairs the study cannot run: every (problem, integrator) whose model build_model() refuses
// (`exact` on a problem with an applied torque), with the refusal's message.
std::vector<Skip> refused_pairs(const std::vector<Problem>& problems);

// Every row of the study, ordered by problem (table order), integrator (registry order), then
// step (coarsest first), except the `skipped` pairs. `progress(done, total)` is called after each
// row, one call at a time.
std::vector<Row> run_grid(const std::vector<Problem>& problems, bool quick, int threads,
                          const TimingSettings& timing, const std::vector<Skip>& skipped,
                          const std::function<void(int, int)>& progress);

// Relative energy error |E(t) - E(0)| / |E(0)| of one integrator on a problem at step dt, every
// step up to t_end (at most ~1000 points kept, evenly spaced in steps). Stops at a divergence.
struct EnergyTrace {
    std::string integrator;
    std::vector<std::pair<double, double>> points; // (t, relative energy error)
    bool diverged = false;
};
EnergyTrace energy_trace(const Problem& p, const std::string& integrator, double dt, double t_end);

} // namespace tumble::app::study
