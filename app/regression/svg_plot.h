#pragma once
// A small SVG plot of one compared series of a state check, for the HTML report: above, the
// quantity of this run against the golden's, with the golden +- tolerance as a band; below, the
// deviation against the tolerance, which stays readable when the tolerance is far smaller than
// the quantity. The first sample out of tolerance is marked. No scripts, no external fonts.
#include "app/regression/check_result.h"

#include <string>

namespace tumble::app {

std::string svg_plot(const Series& series);

} // namespace tumble::app
