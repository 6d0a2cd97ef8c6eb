// Contact stage: one step as its list of stages, each in the file named for it. What each stage
// does and why is at the top of step.cpp. Each stage records its own wall time (profile()).
#include "physics/contact_stage.h"

namespace tumble::physics {

void ContactStage::step(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool) {
    h_ = m.dt;
    const ThreadPool::Serial serial(pool, steps_on_one_thread(m.contact, m.dynamic_bodies.size()));
    stats_.workers = pool.size();
    profile_ = {};
    find(m, s, pool);    // 1. contact_find.cpp
    wake(m, s);          // 2. contact_wake.cpp
    prepare(m, s, pool); // 3. contact_prepare.cpp
    if (manifolds_.empty()) {
        free_flight(m, s, integrate, pool); // contact_substeps.cpp: nothing to solve
    } else {
        impacts(m, s, pool);             // 4. contact_impacts.cpp
        substeps(m, s, integrate, pool); // 5. contact_substeps.cpp: a-d each substep
        apply_impact_shifts(s);          //    contact_impacts.cpp: bounces timed inside the step
    }
    Stopwatch clock;
    store(s);    // 6. contact_store.cpp
    sleep(m, s); // 7. contact_sleep.cpp
    profile_.finish = clock.lap();
}

} // namespace tumble::physics
