#pragma once
// The contact stability map: for each integrator and contact substep count, the largest time step
// at which each of the contact stage's known failures stays away (docs/study.md):
//   stack      n boxes (5, 10, 20) stand for 10 s: no box drifts more than 1 mm sideways or
//              sinks more than 1 cm;
//   ratio      a heavy cube on a light one (1:10, 1:100, 1:1000) holds: no box drifts more than
//              5 mm sideways (its sway while settling into the soft contact's sag) or sinks 1 cm;
//   bullet     a 2 cm ball at 1, 10, 50 m/s does not pass a 1 cm plate (its centre never
//              crosses the plate's mid-plane);
//   top        a sharp-tipped top spun at 100, 300, 1000 rad/s stays above the table (no point
//              of it more than 2 mm below) for 10 s;
//   rest       a resting ball gains no energy over 10 s (E - E0 <= 1e-9 m g r).
// A run that diverges fails. Search: from h = 1/240 s the step doubles while the case holds (to
// at most kMaxContactDt) or halves until it does (down to kMinContactDt), then bisection in log h
// down to a ratio of 1.05 (1.25 in the quick study).
#include "physics/contact_model.h"
#include "physics/scenes/scene.h"

#include <functional>
#include <string>
#include <vector>

namespace tumble::app::study {

inline constexpr double kMinContactDt = 1.0 / 7680.0;
inline constexpr double kMaxContactDt = 1.0 / 30.0;

struct ContactCase {
    std::string family; // "stack", "ratio", "bullet", "top" or "rest"
    double parameter;   // boxes, mass ratio, speed m/s, spin rad/s; 0 for "rest"
    std::string label;  // "stack 10", "ratio 1:100", "bullet 50 m/s", ...
    std::string bound;  // what holding means, for the report
};
std::vector<ContactCase> contact_cases();

// The substep settings mapped: 0 is the default (the fewest with h / n <= 1/1440 s).
std::vector<int> contact_substep_settings(bool quick);

// One run of a case: the worst value of its measure over the run (drift m, depth m, energy J) and
// whether it held. `substeps` and `iterations` 0 with `tolerance`: effort on demand; either set:
// fixed effort (the map uses the defaults and 8 fixed substeps; `tumble explain` passes the
// scene's settings).
struct ContactRun {
    double worst = 0.0;
    bool diverged = false;
    bool held = false;
};
ContactRun run_contact_case(const ContactCase& c, const std::string& integrator, double dt,
                            int substeps, int iterations = 0,
                            double tolerance = physics::kDefaultContactTolerance);

struct ContactStabilityResult {
    ContactCase c;
    std::string integrator;
    int substeps = 0;
    double dt = 0.0;           // largest step found to hold
    bool below_range = false;  // fails already at kMinContactDt
    bool above_range = false;  // holds at kMaxContactDt
    bool holds_default = true; // holds at the default step 1/240 s
    int evaluations = 0;
};

// Every (case, integrator, substeps): all integrators in the full study, the default (rk4) and
// symplectic_euler in the quick one. Case-major, on `threads` threads.
std::vector<ContactStabilityResult> contact_stability_map(bool quick, int threads);

} // namespace tumble::app::study
