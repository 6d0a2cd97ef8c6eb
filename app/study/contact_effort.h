#pragma once
// The contact solver's work-precision view (issue 28): what each effort setting costs per step and
// what it buys, on two contact scenes with opposite needs:
//   rain    the shifted sphere rain of issue 4 (physics/scenes/sphere_rain.h), N = 1000, 5 s:
//           precision is the deepest overlap at the end (the peer benchmark's measure);
//   stack   a column of 10 boxes of 0.2 m standing 10 s (physics/scenes/contact_scenes.h):
//           precision is the largest sideways drift or sinking of any box.
// Settings: effort on demand at contact tolerances from 1 mm to 10 um, and the fixed settings
// before it (480x1: 2 substeps, 1 solve and 1 relax sweep; 1440x3: 6 substeps, 3 and 2). Cost is
// the stepping loop's CPU time per step (median over repetitions), beside the effort counted
// (sweeps per contact point per step). ODE's points come from the peer benchmark's CSV
// (scripts/bench-peers.sh, bench/results/<machine>/peers.csv) where it was built and run.
#include <filesystem>
#include <string>
#include <vector>

namespace tumble::app::study {

struct EffortPoint {
    std::string scene;      // "rain" or "stack"
    std::string setting;    // "tolerance 0.1 mm", "480x1", "1440x3", "ODE (peer benchmark)"
    double tolerance = 0.0; // m; 0 for fixed settings and peers
    int substeps = 0, iterations = 0; // fixed settings; 0: on demand
    double us_per_step = 0.0;         // median CPU time of one step, us
    double error_mm = 0.0;            // rain: deepest overlap at the end; stack: drift or sink
    double sweeps_per_point = 0.0;    // solve and relax sweeps per contact point per step
    double substeps_per_body = 0.0;   // substeps of a body in contact, mean over the run
    bool peer = false;                // measured by the peer benchmark, not in this run
};

// Every scene at every setting; `repetitions` timing runs each (the first also measures), on
// `threads` workers (one run per worker at a time, timed by its own thread's CPU clock).
std::vector<EffortPoint> contact_effort_study(int repetitions, int threads);

// ODE's points from the peer benchmark's summary CSV (rows "rain1000,ode,..." and
// "stack10,ode,..."). Throws io::BadInput naming the file and line when it is not that CSV.
std::vector<EffortPoint> read_peer_points(const std::filesystem::path& csv);

// contact_effort.csv: one row per point.
std::string effort_csv(const std::vector<EffortPoint>& points);

// report.md's section: the table per scene and how to read it.
std::string effort_markdown(const std::vector<EffortPoint>& points);

// plots/contact-effort.png: cost per step against precision, one panel per scene.
void effort_plot(const std::filesystem::path& dir, const std::vector<EffortPoint>& points);

} // namespace tumble::app::study
