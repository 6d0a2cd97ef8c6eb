#pragma once
// Nice numbers for the axes of charts and plots (Heckbert, "Nice numbers for graph labels",
// Graphics Gems, 1990): ranges made of whole steps of 1, 2 or 5 x 10^k, and tick labels printed
// with the digits the step needs and no more ("0.008", not "0.007757").
#include <string>

namespace tumble::render {

// The smallest 1, 2 or 5 x 10^k at least `span` / `intervals` (span > 0).
double nice_step(double span, int intervals = 5);

struct NiceRange {
    double lo = 0.0, hi = 1.0, step = 0.2;
};

// The tightest range of whole steps holding [lo, hi]: lo and hi rounded out to multiples of a
// nice step near a fifth of the span, so each end has less than one step of slack; an end that
// falls exactly on a step gets one step more, so no curve runs along the frame. A flat line
// (lo == hi) gets a span of its own size (1 around 0).
NiceRange nice_range(double lo, double hi, int intervals = 5);

// A multiple of `step` printed with the decimals `step` needs: tick_label(0.008, 0.002) is
// "0.008", tick_label(12, 2) is "12", tick_label(-3e-7, 1e-7) is "-3e-07"; |v| below half a step
// is "0".
std::string tick_label(double v, double step);

} // namespace tumble::render
