#pragma once
// The named integrators a scene (or --integrator) can choose, and their registry.
//
// Each integrator is one file plus one row. Its file, integrator_<name>.cpp, opens with the update
// it performs, its order, what it conserves and how it is known to fail, and defines one
// IntegrateFn. Its row of the registry (kIntegrators in integrator.cpp) gives its handle, name,
// order, what it conserves, a summary and that function. Everything else is read from the table:
// step() calls the row's function, and the command line, `tumble explain`, the study, the tests
// and the benchmarks list the rows.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tumble::physics {

struct Model;
struct State;

// Advances the dynamic bodies listed in `bodies` by one step h under the loads of forces.h, each
// body's update reading and writing only that body's state (so a list may be split between
// threads). step() makes one call per step or substep over the whole list: the per-body loops are
// inside the integrator, with no virtual call per body.
using IntegrateFn = void (*)(const Model& model, State& state, double h,
                             std::span<const int> bodies);

// The handle of a row of the registry: one enumerator per row, in the table's order (integrator.cpp
// checks both at compile time).
enum class Integrator : std::uint8_t {
    Euler,
    EulerMomentum,
    SymplecticEuler,
    ImplicitGyro,
    Rk4,
    Splitting,
    Midpoint,
    Splitting4,
    Exact,
    SplittingExact,
    Splitting4Exact,
    Count // not an integrator: the number of rows
};

struct IntegratorInfo {
    Integrator id;
    std::string_view name;      // as written in scene files and on the command line
    int order;                  // order of accuracy its theory gives on the rotation; kExactOrder
                                // for a method with no truncation error
    std::string_view conserves; // what it keeps exactly or bounded (docs/integrators.md)
    std::string_view summary;   // one line for `tumble explain` and --help
    IntegrateFn integrate;      // defined in integrator_<name>.cpp
    // Cost of one body-step relative to symplectic_euler's, measured (docs/integrators.md, the
    // ns / body-step column; the exact rows by bench/integrators_bench books/*, medians of 3: 808, 809
    // and 4055 against 61 ns): the cost model with which "auto" compares plans (accuracy_plan.h).
    double cost = 1.0;
    // Steps a torque-free body by its exact motion (free_rotation.h): no truncation error without
    // torque, whatever h, and so no order to see on a torque-free scene.
    bool exact_without_torque = false;
    // build_model() refuses a scene with an applied torque (ModelError naming body and `torque`).
    bool refuses_torque = false;
};

// The `order` of a method that truncates nothing on the scenes it accepts (`exact`): its error is
// round-off at every step, whatever h, so no power of h describes it. Zero, so that wherever a
// method is chosen for its order (the study's converged reference) every convergent method ranks
// above it; printed as "exact" (order_text).
inline constexpr int kExactOrder = 0;
std::string order_text(int order); // "2", or "exact" for kExactOrder

std::span<const IntegratorInfo> integrators();
const IntegratorInfo& integrator_info(Integrator id);
std::optional<Integrator> integrator_from_name(std::string_view name);
std::string integrator_names(); // "a, b, c": for error messages

} // namespace tumble::physics
