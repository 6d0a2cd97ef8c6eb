#pragma once
// Overlapping bodies in a state, for checks at load time (not per step): static shapes that
// overlap (refused by build), and bodies that start deeply interpenetrated (a warning).
#include "physics/model.h"
#include "physics/state.h"

#include <vector>

namespace tumble::physics {

struct Overlap {
    int a, b;     // bodies, a < b
    double depth; // m, > 0
};

// Pairs overlapping by more than `min_depth` (m) at the state's poses. `statics_only`: pairs of
// two static bodies only; otherwise pairs with at least one dynamic body. Sweep and prune on x,
// then the narrow phase; in body order (deterministic).
std::vector<Overlap> find_overlaps(const Model& model, const State& state, double min_depth,
                                   bool statics_only);

// The overlaps worth a warning: deeper than 1 cm or than a fifth of the thinner body.
std::vector<Overlap> deep_initial_overlaps(const Model& model, const State& state);

} // namespace tumble::physics
