#pragma once
// A small SVG plot of one compared series of a state check, for the HTML report: a legend row;
// above, the quantity of this run against the golden's, with the golden +- tolerance as a band
// drawn at least 3 px thick (a 1e-6 tolerance on a quantity near 1 would be invisible); below,
// the deviation on a log scale against the tolerance, which stays readable however far the
// tolerance is below the quantity or the deviation above the tolerance. Axes are nice ranges
// with their ticks labelled in the digits their step needs (render/nice_scale.h); titles fit
// the plot's width. The first sample out of tolerance is marked. No scripts, no external fonts.
#include "app/regression/check_result.h"

#include <string>

namespace tumble::app {

std::string svg_plot(const Series& series);

} // namespace tumble::app
