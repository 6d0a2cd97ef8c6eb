#pragma once
// The search both stability maps make (stability.h, contact_stability.h): the largest value of a
// step-like parameter in [min, max] at which a run still passes. From `start` the value doubles
// while the run passes (capped at max) or halves until it does (down to min); then bisection in
// the logarithm between the last pass and the first failure, down to hi / lo <= ratio. Passing
// need not be monotone: the value reported is the first boundary met from `start`.
#include <algorithm>
#include <cmath>

namespace tumble::app::study {

struct Boundary {
    double value = 0.0;       // largest passing value found (min when below_range)
    bool holds_start = false; // passes at `start`
    bool below_range = false; // fails down to min
    bool above_range = false; // passes at max
};

template <class Passes>
Boundary largest_passing(double start, double min, double max, double ratio, Passes&& passes) {
    Boundary b;
    b.holds_start = passes(start);
    double lo = start, hi = start; // lo passes, hi fails
    if (b.holds_start) {
        for (;;) {
            if (lo >= max * (1.0 - 1e-9)) {
                b.value = lo;
                b.above_range = true;
                return b;
            }
            hi = std::min(2.0 * lo, max);
            if (!passes(hi)) break;
            lo = hi;
        }
    } else {
        for (;;) {
            lo = 0.5 * hi;
            if (lo < min * (1.0 - 1e-9)) {
                b.value = min;
                b.below_range = true;
                return b;
            }
            if (passes(lo)) break;
            hi = lo;
        }
    }
    while (hi / lo > ratio) {
        const double mid = std::sqrt(lo * hi);
        (passes(mid) ? lo : hi) = mid;
    }
    b.value = lo;
    return b;
}

} // namespace tumble::app::study
