#pragma once
// The series one figure of `tumble plot` draws: for each run, each body asked for (or the scene's
// totals) and each quantity or component, the value against time.
#include "app/plot/run_files.h"
#include "app/plot/table_values.h"
#include "physics/model.h"

#include <string>
#include <utility>
#include <vector>

namespace tumble::app::plot {

struct Series {
    std::string title;                             // "euler: book: rotational"
    std::vector<std::pair<double, double>> points; // (t in s, value)
};

struct PlotRequest {
    std::vector<Quantity> quantities; // sharing one unit
    std::vector<std::string> bodies;  // by name; empty: the scene's totals
    // The runs' scene, when a quantity needs masses or inertia (else null): its model and the
    // names of its bodies, held against each run's so that a run of another scene is refused.
    const physics::Model* model = nullptr;
    std::vector<std::string> scene_bodies;
    std::string scene_source; // for messages
};

// Checks the options before any file is read: throws io::BadInput (exit 2) naming the option for
// quantities of different units, a body's quantity without --bodies, a scene total that the
// diagnostics do not hold, or a quantity that needs masses without a scene.
void check_request(const PlotRequest& request);

// Which tables the request reads: the states for bodies, the diagnostics for scene totals.
inline bool reads_states(const PlotRequest& r) {
    return !r.bodies.empty();
}
inline bool reads_diagnostics(const PlotRequest& r) {
    return r.bodies.empty();
}

// Throws io::BadInput (exit 2) for a body no run has, a scene whose bodies are not the run's, a
// quantity the request cannot give (a body's without --bodies, a scene total that does not exist)
// or a drift relative to a zero energy.
std::vector<Series> make_series(const std::vector<Run>& runs, const PlotRequest& request);

} // namespace tumble::app::plot
