// Contact stage, sleep (Box2D's islands). A body is slow when no point of it moves faster than
// the sleep speed: max(|v|, |w| R) < v_sleep, R being its bounding radius about the centre of
// mass. Bodies linked by contacts form an island (union-find over this step's manifolds between
// two dynamic bodies; static bodies link nothing), and an island sleeps when all its bodies have
// been slow for time_to_sleep: v = w = 0, no integration, no solving, until an awake body touches
// one of them (contact_wake.cpp) and the whole island wakes. A sleeping island's contacts keep
// their manifolds and impulses, so it wakes warm-started.
#include "physics/contact_stage.h"
#include "physics/union_find.h"

#include <algorithm>

namespace tumble::physics {

void ContactStage::sleep(const Model& m, State& s) {
    stats_.awake = 0;
    for (int i : m.dynamic_bodies) stats_.awake += awake_[i];
    if (!m.contact.sleeping) return;
    const int n = m.body_count();
    const double limit2 = m.contact.sleep_speed * m.contact.sleep_speed;
    for (int i : m.dynamic_bodies) {
        if (!awake_[i]) continue;
        const double e = bounding_radius(m, i); // can_touch.h
        const double speed2 = std::max(s.v[i].squaredNorm(), s.w[i].squaredNorm() * e * e);
        s.sleep.slow_time[i] = speed2 < limit2 ? s.sleep.slow_time[i] + h_ : 0.0;
    }
    parent_.resize(n);
    for (int i = 0; i < n; ++i) parent_[i] = i;
    const ContactCache& contacts = s.contacts; // this step's, stored by store()
    for (int k = 0; k < contacts.size(); ++k) {
        const int a = pair_first(contacts.pair[k]), b = pair_second(contacts.pair[k]);
        if (awake_[a] && awake_[b]) parent_[union_root(parent_, a)] = union_root(parent_, b);
    }
    // Per island root: the shortest slow time and the smallest member (the island's name).
    island_slow_.assign(n, 1e300);
    island_min_.assign(n, n);
    for (int i : m.dynamic_bodies) {
        if (!awake_[i]) continue;
        const int r = union_root(parent_, i);
        island_slow_[r] = std::min(island_slow_[r], s.sleep.slow_time[i]);
        island_min_[r] = std::min(island_min_[r], i);
    }
    for (int i : m.dynamic_bodies) {
        if (!awake_[i]) continue;
        const int r = union_root(parent_, i);
        if (island_slow_[r] < m.contact.time_to_sleep) continue;
        s.sleep.asleep[i] = 1;
        s.sleep.island[i] = island_min_[r];
        s.v[i] = Vec3::Zero();
        s.w[i] = Vec3::Zero();
    }
}

} // namespace tumble::physics
