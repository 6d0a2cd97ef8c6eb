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

struct OverlayInfo {
    double t = 0.0;        // s
    std::int64_t step = 0; // steps taken since t = 0
    std::string_view integrator;
    double h = 0.0; // s
    physics::Diagnostics now, initial;
    // Whose numbers they are: empty for the scene's sums (L about the origin), else a body's
    // name (its own energy, momentum and spin L about its centre of mass).
    std::string_view subject;
};

// Replaces `lines` (reusing their storage) with the overlay text.
void overlay_lines(const OverlayInfo& info, std::vector<std::string>& lines);

} // namespace tumble::app
