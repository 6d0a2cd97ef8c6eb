#pragma once
// The contact solver's effort over a run (issue 28): the sums of ContactStats::effort step by
// step, described in one line for the run summary of `tumble render` and `tumble simulate` and for
// `tumble explain`'s pilot run.
#include "physics/contact_model.h"
#include "physics/contact_stage.h"

#include <string>

namespace tumble::physics {

struct EffortTally {
    long long steps = 0;        // steps counted
    long long solved_steps = 0; // of which solved contacts
    double islands = 0;         // island-steps
    int islands_max = 0;        // most islands in one step
    double bodies = 0;          // body-steps in islands
    double body_substeps = 0;   // sum over those of their island's substeps
    double points = 0;          // contact point-steps
    double point_sweeps = 0;    // sum over those of the sweeps that solved them
    int substeps_min = 0, substeps_max = 0, sweeps_max = 0;
    long long capped_substeps = 0;

    void add(const ContactStats& stats);

    // "contact effort on demand (tolerance 0.1 mm) over 1200 steps: ..." or, for a scene that
    // fixes it, the fixed counts and what they cost per contact point.
    std::string describe(const ContactSettings& settings, double h) const;
};

} // namespace tumble::physics
