#pragma once
// A run's states and diagnostics as flat arrays, one row per sampled step: what the Python
// module's simulate() returns (tumble.Trajectory), its arrays NumPy views of these vectors. The
// values are those `tumble simulate` prints (app/run/trajectory_rows.h makes both), so the
// arrays equal the CSV's numbers, and write_csv() prints the CSV itself.
#include "app/run/prepare_run.h"
#include "app/run/trajectory_rows.h"
#include "physics/error_estimate.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tumble::python {

struct Trajectory {
    app::Scene scene; // as it ran ("auto" resolved), for write_csv()'s names and estimate columns
    std::string integrator;
    double h = 0.0; // the step, s
    int fps = 0;
    // The moving (dynamic) bodies, in the scene's order: the arrays' second axis.
    std::vector<int> body;
    std::vector<std::string> names;
    // The static bodies' rows at t = 0 (they never move), for write_csv(); indexed like `all`.
    std::vector<app::StateRow> static_rows;
    std::int64_t rows = 0;
    std::vector<std::int64_t> step;
    std::vector<double> t;                          // (T,) s
    std::vector<double> position, velocity, w;      // (T, B, 3): origin m, m/s, rad/s (world)
    std::vector<double> orientation;                // (T, B, 4): w, x, y, z
    std::vector<double> kinetic, potential, energy; // (T,) J
    std::vector<double> momentum, angular_momentum; // (T, 3) kg m/s, kg m^2/s (origin)
    // The error estimate when the run carried one: per row, one entry per moving body
    // (physics::BodyEstimate: holds() false once a contact or sleep ended it).
    int estimate_bodies = 0;
    std::vector<physics::BodyEstimate> estimate; // (T, estimate_bodies)
    std::vector<std::string> notes;              // what the CLI prints as "note:" (dt lowered, ...)
    std::vector<std::string> summary;            // the auto choice, the estimate, the tolerance
    std::vector<std::string> tolerance_missed;   // warnings, each naming body and amount

    // Appends the row of `sim`'s current state.
    void record(const app::Simulation& sim);
    // The CLI's two CSV files (app/run/trajectory_writer.h), byte for byte those of `tumble
    // simulate` with the same --every; an empty `diagnostics` writes none. Throws io::BadInput
    // for a path that cannot be used, std::runtime_error when writing fails.
    void write_csv(const std::string& states, const std::string& diagnostics) const;
};

// Starts a trajectory of `run` (at t = 0): its bodies, names and the first row.
Trajectory start_trajectory(const app::PreparedRun& run);

// Steps `run` to the end of its timeline (t = duration, as `tumble simulate`), recording step 0,
// every `every`-th step and the last. Returns false when Ctrl-C stopped it (io/interrupt.h).
bool simulate_into(app::PreparedRun& run, int every, Trajectory& out);

} // namespace tumble::python
