// Contact stage, wake: an awake body touching a sleeping one wakes the sleeper's whole island
// (islands and sleeping: contact_sleep.cpp). A woken island is solved this step, warm-started by
// the impulses its contacts kept while it slept.
#include "physics/contact_stage.h"

#include <algorithm>

namespace tumble::physics {

void ContactStage::wake(const Model& m, State& s) {
    if (!m.contact.sleeping) return;
    island_min_.clear();
    for (int k = 0; k < narrow_count_; ++k) {
        const int a = pair_first(next_.pair[k]), b = pair_second(next_.pair[k]);
        for (const auto& [sleeper, other] : {std::pair{a, b}, std::pair{b, a}})
            if (m.is_dynamic(sleeper) && !awake_[sleeper] && awake_[other])
                island_min_.push_back(s.sleep.island[sleeper]);
    }
    if (island_min_.empty()) return;
    std::sort(island_min_.begin(), island_min_.end());
    for (int i : m.dynamic_bodies) {
        if (!s.sleep.asleep[i] ||
            !std::binary_search(island_min_.begin(), island_min_.end(), s.sleep.island[i]))
            continue;
        s.sleep.asleep[i] = 0;
        s.sleep.slow_time[i] = 0.0;
        awake_[i] = 1;
    }
}

} // namespace tumble::physics
