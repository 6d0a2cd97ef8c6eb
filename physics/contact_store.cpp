// Contact stage, store: this step's impulses into the contacts found this step, which then become
// the State's contact cache (contact_cache.h): the warm start of the next step, carried by the
// State so that a copied State continues bit-identically.
#include "physics/contact_stage.h"

#include <utility>

namespace tumble::physics {

void ContactStage::store(State& s) {
    for (const SolverManifold& c : manifolds_) {
        const SolverPoint* pts = &points_[c.first];
        for (int j = 0; j < c.count; ++j) {
            CachedPoint& q = next_.points[next_.first[c.cache] + j];
            q.normal_impulse = pts[j].normal_impulse;
            q.friction_impulse =
                pts[j].friction_impulse[0] * c.t1 + pts[j].friction_impulse[1] * c.t2;
        }
    }
    std::swap(s.contacts, next_);
    stats_.manifolds = s.contacts.size();
}

} // namespace tumble::physics
