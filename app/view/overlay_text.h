#pragma once
// The numbers in the corner of a frame (render.overlay / --overlay): simulated time and step,
// the integrator and its step size, total energy with its drift since t = 0, linear and angular
// momentum. Fixed-width fields, so with the monospaced overlay font the text does not jiggle as
// the numbers change.
#include "physics/diagnostics.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tumble::app {

// The error estimate's line (physics/error_estimate.h): the largest estimate over the bodies whose
// estimate holds, and how many bodies it no longer holds for (contacts, sleep).
struct OverlayEstimate {
    bool on = false;
    double rotation = 0.0, position = 0.0; // rad, m
    int holding = 0, not_holding = 0;
};

struct OverlayInfo {
    double t = 0.0;        // s
    std::int64_t step = 0; // steps taken since t = 0
    std::string_view integrator;
    double h = 0.0; // s
    physics::Diagnostics now, initial;
    // Whose numbers they are: empty for the scene's sums (L about the origin), else a body's
    // name (its own energy, momentum and spin L about its centre of mass).
    std::string_view subject;
    OverlayEstimate estimate; // a line of its own when on
};

// Replaces `lines` (reusing their storage) with the overlay text. `compact`, for a small frame
// or tile (app/view/overlay_layout.h decides): the integrator and step, the time and the energy
// drift, each line at most 24 characters, plus the estimate's when on.
void overlay_lines(const OverlayInfo& info, std::vector<std::string>& lines, bool compact = false);

} // namespace tumble::app
