#pragma once
// The cases of the peer benchmark (peers_bench.cpp): each runs one scene once with one engine and
// settings, and the summary gives medians and ratios against ODE measured in the same run.
#include "bench/peers/ode_world.h"

#include <string>
#include <vector>

namespace tumble::bench {

struct Options {
    int reps[3] = {5, 3, 3}; // rain 1000, rain 8000, stack 10
    std::string only;        // comma-separated scenes; empty: all
    std::string csv;         // where the summary goes as CSV; empty: nowhere
    OdeSpace space = OdeSpace::SweepAndPrune;
    // Contact tolerances (world.contact_tolerance, m) to run effort on demand at besides the
    // default, each as a case "tumble/tol:<mm>mm": what loosening the knob buys against ODE.
    std::vector<double> tolerances;
};

int run_peers(const Options& options);

} // namespace tumble::bench
