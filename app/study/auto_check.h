#pragma once
// `tumble study --auto`: accuracy as a setting, verified against the exact oracles. For every
// problem with an exact or closed-form reference and every tolerance from 1e-2 to 1e-8:
//   1. "auto" plans the problem (physics/accuracy_plan.h) at steps h = (T / kSamples) / k, so that
//      its steps land on the sample times like the grid's;
//   2. the chosen run is stepped with the step-doubling estimate (physics/error_estimate.h) and
//      compared with the reference at the sample times: the true error and the estimate, both as
//      the largest over the samples and bodies of max(rotation, position);
//   3. the checks: the estimate within a factor of 3 of the true error; the true error within the
//      tolerance; the chosen run's cost at most 2 x the cheapest grid row that met the tolerance,
//      by the planner's cost model (deterministic) and by the grid's measured times.
// A problem whose bodies touch (the estimate does not hold after a contact) is reported with
// `covered` false and kept out of the three rates: what the estimate does not cover, it cannot
// promise.
#include "app/study/study.h"

#include <string>
#include <vector>

namespace tumble::app::study {

struct AutoCase {
    std::string problem;
    double tolerance = 0.0;
    bool covered = true; // every body's estimate holds over the whole run
    bool found = false;  // the planner met the tolerance within its step limit
    std::string integrator;
    std::int64_t steps = 0;
    double dt = 0.0;
    int pilots = 0;
    double pilot_seconds = 0.0;
    double estimate = 0.0;  // max over samples and bodies of max(rotation, position) estimates
    double truth = 0.0;     // the same of the true error against the reference
    double ratio = 0.0;     // estimate / truth
    bool within_3 = false;  // 1/3 <= ratio <= 3, or both at round-off (below kRoundOff)
    bool round_off = false; // estimate and truth both below kRoundOff: noise, not a step error
    bool meets = false;     // truth <= tolerance
    // The cheapest grid row that met the tolerance (true error, max over the samples).
    std::string cheapest;             // "rk4 n=400", or empty if no row met it
    double cost_ratio_model = 0.0;    // chosen / cheapest, the planner's cost model
    double cost_ratio_measured = 0.0; // chosen / cheapest, the grid's measured ns / body-step
    bool cost_within_2 = false;       // cost_ratio_model <= 2 (none on the grid met it: true)
};

// Below this both the estimate and the true error are round-off (1e4 times below the tightest
// tolerance checked): their ratio is the ratio of two noises, and the case counts as agreeing; the
// report lists such cases as "round-off" and gives the strict count too.
inline constexpr double kRoundOff = 1e-12;

struct AutoSummary {
    int cases = 0, covered = 0, within_3 = 0, within_3_strict = 0, meets = 0, cost_within_2 = 0;
};

// The tolerances checked: 1e-2, 1e-3, ..., 1e-8.
std::vector<double> auto_tolerances();

// Runs the check on `problems` (those without an exact or closed-form reference are skipped) with
// `grid` the study's rows for them (run_grid, same `quick`); cases are shared by `threads` workers.
std::vector<AutoCase> check_auto(const std::vector<Problem>& problems, const std::vector<Row>& grid,
                                 const std::vector<double>& tolerances, bool quick, int threads);

AutoSummary summarise(const std::vector<AutoCase>& cases);

// The Markdown section of report.md and auto.csv's text.
std::string auto_markdown(const std::vector<AutoCase>& cases);
std::string auto_csv(const std::vector<AutoCase>& cases);

} // namespace tumble::app::study
