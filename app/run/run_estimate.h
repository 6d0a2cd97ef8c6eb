#pragma once
// The error estimate of a run (world.error_estimate, --error-estimate): the physics estimator
// (physics/error_estimate.h) riding along a Simulation, the estimates kept at the chosen times, and
// the words the run summary, the diagnostics CSV and the overlay say about them.
#include "app/scene/scene.h"
#include "app/view/overlay_text.h"
#include "physics/error_estimate.h"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace tumble::app {

struct Simulation;

// The estimates at one chosen time, kept as they were at its step.
struct TimedEstimate {
    double asked = 0.0;    // s, as given
    std::int64_t step = 0; // the nearest step, round(asked / h)
    bool reached = false;  // the run got there
    std::vector<physics::BodyEstimate> bodies;
};

struct SimulationEstimate {
    std::unique_ptr<physics::ErrorEstimator> estimator;
    std::vector<TimedEstimate> times;
};

// Turns the estimate on for `sim` (at its current state) when the scene asks for it.
void start_error_estimate(Simulation& sim, const Scene& scene, int threads = 1);

// After each step of `sim`: advances the shadow and keeps the estimates of a chosen time.
void advance_error_estimate(Simulation& sim);

// The run summary's lines (without the "tumble: " prefix): per dynamic body the estimate at the
// end, at each chosen time and its maximum, or where it stopped holding.
std::vector<std::string> estimate_summary(const Simulation& sim);

// The diagnostics CSV's columns: ",err_rad_<body>,err_m_<body>" per dynamic body, and one row's
// values (empty once a body's estimate no longer holds).
std::string estimate_csv_header(const physics::ErrorEstimator& e);
void print_estimate_csv(std::FILE* out, const physics::ErrorEstimator& e);
// The same for estimates kept earlier (one per dynamic body, as ErrorEstimator::bodies()).
std::string estimate_csv_header(std::span<const physics::BodyEstimate> bodies);
void print_estimate_csv(std::FILE* out, std::span<const physics::BodyEstimate> bodies);

// What the overlay shows (app/view/overlay_text.h): the largest estimate over the bodies that hold
// (only `body` when >= 0), and how many no longer hold.
OverlayEstimate estimate_overlay(const physics::ErrorEstimator& e, int body = -1);

} // namespace tumble::app
