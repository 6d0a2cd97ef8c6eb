#pragma once
// The stability map: for each integrator and each set of principal moments, the largest h|w| at
// which a torque-free tumbling body keeps its energy within 10% over 10000 steps.
//
// Moments run from the sphere (1 : 1 : 1) through flat plates (1 : k : 1 + k, the limit of the
// triangle inequality: a lamina) and thin rods (1/k : 1 : 1), k = 10 .. 1e6; every set is a
// physically valid inertia. The body starts at the identity with w = (1, 1, 1) / sqrt(3) rad/s in
// its principal axes (a tumble about no principal axis), so h|w| = h.
//
// Search: h|w| doubles from kMinHw until the run fails (energy off by more than 10% at some step,
// or a divergence), then bisection in log(h|w|) between the last pass and the first failure down
// to a ratio of 1.01 (1.05 in the quick study). A method that passes at kMaxHw is reported as
// "> kMaxHw"; one that fails at kMinHw as "< kMinHw". Stability need not be monotone in h; the
// value reported is the first boundary met going up from kMinHw.
#include "physics/math.h"

#include <string>
#include <vector>

namespace tumble::app::study {

inline constexpr double kMinHw = 1e-4;
inline constexpr double kMaxHw = 100.0;
inline constexpr int kStabilitySteps = 10000;
inline constexpr double kStabilityEnergyTolerance = 0.1;

struct InertiaCase {
    std::string family; // "sphere", "plate" or "rod"
    double k = 1.0;
    physics::Vec3 moments;
};
std::vector<InertiaCase> stability_cases(bool quick);

struct StabilityResult {
    InertiaCase inertia;
    std::string integrator;
    double h_w = 0.0;         // largest h|w| found stable (kMinHw or kMaxHw at the range ends)
    bool below_range = false; // fails already at kMinHw
    bool above_range = false; // passes at kMaxHw
    int evaluations = 0;      // runs of kStabilitySteps made
};

// True when the body keeps |E - E0| <= 0.1 E0 at every one of kStabilitySteps steps of h|w|.
bool keeps_energy(const std::string& integrator, const physics::Vec3& moments, double h_w);

// Every (inertia case, integrator of the registry), case-major, on `threads` threads.
std::vector<StabilityResult> stability_map(bool quick, int threads);

} // namespace tumble::app::study
