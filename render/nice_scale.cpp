#include "render/nice_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::render {

double nice_step(double span, int intervals) {
    const double raw = span / std::max(1, intervals);
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / decade; // in [1, 10)
    // 1.0000001: a span that is a whole number of steps up to rounding keeps that step.
    const double pick = m <= 1.0000001 ? 1 : m <= 2.0000001 ? 2 : m <= 5.0000001 ? 5 : 10;
    return pick * decade;
}

NiceRange nice_range(double lo, double hi, int intervals) {
    if (!(hi > lo)) { // a flat line: a span of its own size around it
        const double half = lo == 0.0 ? 0.5 : 0.5 * std::abs(lo);
        lo -= half, hi += half;
    }
    NiceRange r;
    r.step = nice_step(hi - lo, intervals);
    r.lo = std::floor(lo / r.step) * r.step;
    r.hi = std::ceil(hi / r.step) * r.step;
    if (r.lo == lo) r.lo -= r.step; // room below and above the curve
    if (r.hi == hi) r.hi += r.step;
    return r;
}

std::string tick_label(double v, double step) {
    if (std::abs(v) < 0.5 * step) return "0";
    const int p = int(std::floor(std::log10(step) + 1e-9)); // step = m 10^p, m in {1, 2, 5}
    char text[40];
    if (p >= -4 && p <= 5) {
        std::snprintf(text, sizeof text, "%.*f", std::max(0, -p), v);
    } else {
        const int e = int(std::floor(std::log10(std::abs(v)) + 1e-9));
        std::snprintf(text, sizeof text, "%.*e", std::max(0, e - p), v);
    }
    return text;
}

} // namespace tumble::render
