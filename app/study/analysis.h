#pragma once
// What the study concludes from its rows: the measured order of each integrator on each problem,
// and the cheapest (integrator, step) that reaches each target orientation error.
#include "app/study/study.h"

#include <string>
#include <vector>

namespace tumble::app::study {

// Errors inside this window enter the order fit: above it the run is not yet asymptotic (a flip
// half a turn late), below it round-off takes over.
inline constexpr double kFitMaxError = 1e-1;
inline constexpr double kFitMinError = 1e-10;

// Least-squares slope of log(orientation error, maximum over the run) against log(dt), over the
// rows of one (problem, integrator) whose error lies in [kFitMinError, kFitMaxError] and that did
// not diverge. NaN when fewer than three rows qualify, and for a method that truncates nothing on
// the problem (Row::exact_here, theory physics::kExactOrder): its errors are round-off, which
// grows as h shrinks (more steps), and no slope describes it.
struct OrderFit {
    std::string problem, integrator;
    int theory = 0; // the registry's order; 1 on a contact problem; kExactOrder where exact_here
    double measured = 0.0;
    int points = 0;
};
std::vector<OrderFit> fit_orders(const std::vector<Row>& rows);

// The recommendation for one (problem, target): among rows of the problem whose orientation error
// (maximum over [0, T]) is at most `target` at their step *and at every finer step of the same
// integrator* (so that a lucky cancellation at one step is not recommended), the one with the
// smallest measured cost (time to simulate [0, T]). `row` is null when no row reaches the target.
struct Recommendation {
    std::string problem;
    double target = 0.0;
    const Row* row = nullptr;
};
inline constexpr double kTargets[] = {1e-2, 1e-4, 1e-6};
std::vector<Recommendation> recommend(const std::vector<Row>& rows,
                                      const std::vector<std::string>& problems);

// True when `r` meets `target` at its own step and at every finer step of its integrator.
bool reaches(const std::vector<Row>& rows, const Row& r, double target);

} // namespace tumble::app::study
