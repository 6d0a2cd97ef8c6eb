#pragma once
// `tumble study`: the work-precision study. Every reference problem (study_problems.cpp) is run
// with every registered integrator (physics::integrators()) over a log-spaced grid of time steps;
// each run is compared with the problem's reference motion (an exact oracle, or a converged run at
// a much smaller step) and timed. docs/study.md describes the method and the outputs.
//
// Files: study_problems.cpp (the table), study_metrics.cpp (errors against a reference),
// study_runner.cpp (accuracy and timing runs, worker threads), study_analysis.cpp (fitted orders,
// recommendations), study_stability.cpp (stability map), study_report.cpp (CSV, JSON, Markdown),
// study_plots.cpp (gnuplot), study_command.cpp (the subcommand).
#include "physics/build.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tumble::app::study {

// Errors are sampled at kSamples evenly spaced times t_j = j T / kSamples (j = 1 .. kSamples), so
// every step count on the grid is a multiple of kSamples and every sample time is hit exactly.
inline constexpr int kSamples = 50;

// Where a problem's reference motion comes from.
enum class ReferenceKind {
    Exact,        // the oracles of physics/exact (ExactBodyMotion per dynamic body)
    ConvergedRun, // a run of the registry's highest-order integrator at a much smaller step
    Analytic,     // Problem::analytic: a closed form of the whole scene (contacts: bounces, rest)
};

struct StepRange {
    double h_max = 0.0; // s, coarsest step (rounded so that T / h is a multiple of kSamples)
    double h_min = 0.0; // s, finest step
    int per_decade = 4; // grid points per decade of h
};

struct Problem {
    std::string name;        // used in file names and as the CSV key
    std::string description; // one line for the report
    std::function<physics::WorldDef()> world;
    std::function<std::vector<physics::BodyDef>()> bodies;
    double duration = 1.0; // T, s: errors "at the end" are at t = T
    ReferenceKind reference = ReferenceKind::Exact;
    int reference_refine = 16; // ConvergedRun: reference step = finest grid step / this
    StepRange full, quick;
    // ReferenceKind::Analytic: sets the dynamic bodies of `state` (the initial state on entry)
    // to the exact motion at time t.
    std::function<void(double t, const physics::Model& model, physics::State& state)> analytic = {};
    // A contact problem: its error is dominated by the contact stage, which is first order
    // whatever the integrator (impacts, and x += h v for bodies in contact: docs/contacts.md), and
    // its bodies need not turn. Orders, plots and recommendations then judge the position error
    // and expect order 1.
    bool contacts = false;
};

// The reference problems, in report order; the first is the headline (intermediate-axis flip).
// Adding a problem (a contact scene with a converged reference, say) is one entry in this table.
const std::vector<Problem>& problems();

// The step counts n (multiples of kSamples) of a problem's grid, coarsest first.
std::vector<std::int64_t> step_counts(const Problem& p, bool quick);

// Errors of a run against the reference at one time (study_metrics.h defines them).
struct Errors {
    double position = 0.0;         // max over bodies of |x - x_ref|, m
    double orientation = 0.0;      // max over bodies of the angle of R_ref^T R, rad
    double angular_velocity = 0.0; // max over bodies of |w - w_ref| / |w_ref|
    double energy = 0.0;           // |E - E_ref| / |E_ref|, whole system
    double momentum = 0.0;         // |L - L_ref| / |L_ref|, world, about the origin
};

// One (problem, integrator, step) run.
struct Row {
    std::string problem;
    std::string integrator;
    int order = 0;  // the registry's theoretical order
    int bodies = 0; // dynamic bodies
    double dt = 0.0;
    std::int64_t steps = 0;
    double h_w = 0.0; // dt * the largest initial |w| of the problem's bodies
    Errors end;       // at t = T
    Errors max;       // maximum over the samples t_j (including T)
    bool diverged = false;
    int diverged_body = -1;
    std::int64_t diverged_step = -1;
    std::string diverged_quantity;
    // Cost: median over repetitions of the wall time of the stepping loop alone.
    double ns_per_body_step = 0.0;
    double steps_per_second = 0.0; // whole-scene steps per second
    double cost_s = 0.0;           // time to simulate [0, T]: ns_per_body_step * bodies * steps
    int repetitions = 0;
    bool contacts = false; // the problem's: headline_error() is the position error
    // The integrator truncates nothing on this problem (IntegratorInfo::exact_without_torque on a
    // problem without applied torques or contacts): its error is round-off at every step, and it
    // has no order to fit.
    bool exact_here = false;
};

// A (problem, integrator) pair the study does not run, and why: `exact` refuses a problem with
// an applied torque (its ModelError's message, naming the body).
struct Skip {
    std::string problem, integrator, reason;
};

// The error a row is judged by (order fits, plots, recommendations): the orientation error over
// the run, or for a contact problem the position error.
inline double headline_error(const Row& r) {
    return r.contacts ? r.max.position : r.max.orientation;
}

} // namespace tumble::app::study
