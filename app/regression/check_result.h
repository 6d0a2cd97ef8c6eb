#pragma once
// What running one check of a suite found: passed or not, one line saying why, further lines,
// and what the reports show (images of an image check; the compared series of a state check).
#include "app/regression/suite.h"
#include "app/run/trajectory_rows.h"
#include "render/image.h"
#include "render/image_compare.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tumble::app {

// The GL renderer that drew an image (glGetString), as a golden records it.
struct GlIdentity {
    std::string renderer, version; // both empty: not recorded
    bool known() const { return !renderer.empty() || !version.empty(); }
    bool operator==(const GlIdentity&) const = default;
    std::string describe() const; // "\"llvmpipe (...)\" / \"4.5 (Core Profile) Mesa 22.3.6\""
};

struct ImageOutcome {
    render::Image actual;   // as drawn (masks not applied)
    render::Image expected; // the golden; empty when missing or unreadable
    render::CompareResult compare;
    GlIdentity golden_gl; // what made the golden (golden-renderers.json)
};

// One compared (body, quantity) or (scene, quantity) pair over the sampled frames.
struct Series {
    std::string body; // empty for the scene's energy and momenta
    StateQuantity quantity = StateQuantity::kPosition;
    double tolerance = 0.0;
    std::vector<std::int64_t> frames;
    std::vector<double> t, deviation; // |actual - golden| in the quantity's unit
    // A scalar for a plot: the vector component that differs most (component names it), or the
    // angle turned since the first sample for an orientation.
    std::string component;
    std::vector<double> actual, golden;
    int first_out = -1;    // first sample out of tolerance; -1: none
    std::size_t worst = 0; // the sample of the largest deviation
    bool passed() const { return first_out < 0; }
    double ratio() const; // largest deviation / tolerance (inf for a zero tolerance missed)
};

// The states a state check sampled: per frame, its bodies' rows and the scene's diagnostics.
struct Sample {
    std::int64_t frame = 0;
    std::vector<StateRow> bodies; // in the check's order of bodies
    DiagnosticsRow diagnostics;
};

struct StateOutcome {
    std::vector<Sample> samples;
    std::vector<Series> series; // failing pairs first would be the report's business: check order
};

struct CheckResult {
    const SuiteScene* scene = nullptr;
    const ImageCheck* image = nullptr; // exactly one of image and state
    const StateCheck* state = nullptr;
    bool passed = false;
    bool run_failed = false; // the scene's run stopped (a divergence, no GL): nothing judged
    bool golden_missing = false;
    bool golden_from_other_gl = false; // recorded and different from this machine's
    std::string summary;               // one line
    std::vector<std::string> details;  // further lines (each pair out of tolerance, notes)
    std::string update;                // the command that would rewrite its golden (failures)
    double seconds = 0.0;              // drawing (or sampling) and comparing
    ImageOutcome image_outcome;
    StateOutcome state_outcome;

    const std::string& name() const { return image ? image->name : state->name; }
    const char* kind() const { return image ? "image" : "state"; }
};

struct SuiteRun {
    GlIdentity gl;                     // this machine's; empty when nothing was drawn
    std::vector<CheckResult> results;  // in suite order
    std::vector<double> scene_seconds; // wall time of each scene's pass, by scene index
    double seconds = 0.0;
    int jobs = 1;
    bool interrupted = false; // Ctrl-C or SIGTERM: scenes not yet started were not run
    std::size_t failed() const;
};

} // namespace tumble::app
