#pragma once
// The contact stage's part of the State: everything a step carries into the next one, so that a
// copied State continues bit-identically. Flat arrays, one entry per manifold (a pair of bodies in
// contact) and one per contact point. Written only by the contact stage: each step finds its
// manifolds with last step's impulses carried over by feature id (contact_find.cpp) and stores
// its own impulses into them before they replace the State's (contact_store.cpp).
#include "physics/math.h"

#include <cstdint>
#include <vector>

namespace tumble::physics {

struct CachedPoint {
    Vec3 point;            // world, midway between the surfaces, m
    double separation;     // along the normal, m (negative: overlap)
    std::uint32_t id;      // feature id: equal ids on consecutive steps = the same contact
    double normal_impulse; // N s, accumulated over the last step (warm start)
    Vec3 friction_impulse; // N s, world (projected onto the new tangents when warm starting)
};

struct ContactCache {
    std::vector<std::uint64_t> pair; // per manifold: (a << 32) | b with body a < body b
    std::vector<Vec3> normal;        // per manifold: unit, from a to b
    std::vector<int> first;          // per manifold: its first point in `points`
    std::vector<int> count;          // per manifold: 1..4 points
    std::vector<CachedPoint> points;

    int size() const { return static_cast<int>(pair.size()); }
    void clear() { pair.clear(), normal.clear(), first.clear(), count.clear(), points.clear(); }
};

// Sleeping: a body at rest (with everything it touches) for time_to_sleep stops being simulated
// until something awake touches it. Sized to the body count for every model by initial_state()
// (build.h); written only by the contact stage's wake (contact_wake.cpp: clears asleep and
// slow_time) and sleep (contact_sleep.cpp: counts slow_time, sets asleep and island).
struct SleepState {
    std::vector<std::uint8_t> asleep; // per body: 1 while asleep (v = w = 0, not integrated)
    std::vector<double> slow_time;    // per body: s it has been slower than the sleep speed
    std::vector<int> island;          // per sleeping body: its island (the smallest body index)
};

inline std::uint64_t pair_key(int a, int b) {
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}
inline int pair_first(std::uint64_t key) {
    return static_cast<int>(key >> 32);
}
inline int pair_second(std::uint64_t key) {
    return static_cast<int>(key & 0xffffffffu);
}

} // namespace tumble::physics
