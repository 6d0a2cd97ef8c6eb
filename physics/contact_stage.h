#pragma once
// The contact stage of one step (the pipeline is documented at the top of step.cpp). Holds only
// scratch: everything that carries over between steps lives in the State (contact_cache.h), so
// the stage can be shared by any number of states and a copied State continues bit-identically.
// Every buffer keeps its capacity, so a step allocates nothing once the scene has warmed up.
#include "physics/broadphase.h"
#include "physics/collide.h"
#include "physics/contact_solver.h"
#include "physics/integrator.h"
#include "physics/thread_pool.h"

#include <chrono>
#include <cstdint>
#include <exception>
#include <span>
#include <vector>

namespace tumble::physics {

// Milliseconds since the last lap (steady clock), for the profile.
class Stopwatch {
  public:
    Stopwatch() : last_(std::chrono::steady_clock::now()) {}
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }

  private:
    std::chrono::steady_clock::time_point last_;
};

// Counts of the last step, for benchmarks, `tumble explain`-style summaries and tests.
struct ContactStats {
    int pairs = 0;       // broad-phase candidate pairs
    int manifolds = 0;   // pairs with contact points (touching or speculative)
    int points = 0;      // contact points
    int constraints = 0; // manifolds with a body that moves (solved)
    int colours = 0;     // graph colours used (parallel batches)
    int impacts = 0;     // impact sweeps that applied an impulse
    int awake = 0;       // dynamic bodies simulated (not asleep)
    int substeps = 0;
    int sweeps = 0;         // solve plus relax sweeps per substep
    int workers = 1;        // threads the step used (ContactSettings::parallel_min_bodies)
    double max_overlap = 0; // m, deepest contact point at the start of the step
};

// Wall time of the last step's stages, ms (Box2D's b2Profile).
struct ContactProfile {
    double broad = 0, narrow = 0, prepare = 0, impacts = 0, solve = 0, integrate = 0, finish = 0;
};

class ContactStage {
  public:
    static constexpr int kColours = 32;        // colours tried before a constraint overflows
    static constexpr int kOverflow = kColours; // the last batch: one worker, in order
    static constexpr int kColourGrain = 64;    // a colour this small runs on one worker

    // Advances `s` by one step of the model (contacts, then `integrate` per substep).
    void step(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool);
    const ContactStats& stats() const { return stats_; }
    const ContactProfile& profile() const { return profile_; }

  private:
    // 1. find (contact_find.cpp)
    void find(const Model& m, const State& s, ThreadPool& pool);
    void sweep_bounds(const Model& m, const State& s, ThreadPool& pool);
    void broad_phase(const Model& m, ThreadPool& pool);
    void index_old_contacts(const ContactCache& old);
    int old_manifold(std::uint64_t key) const; // in last step's contacts, or -1
    void narrow_phase(const Model& m, const State& s, ThreadPool& pool);
    void merge_found(const ContactCache& old);
    // 2. wake (contact_wake.cpp)
    void wake(const Model& m, State& s);
    // 3. prepare (contact_prepare.cpp)
    void prepare(const Model& m, const State& s, ThreadPool& pool);
    void prepare_bodies(const Model& m, const State& s, ThreadPool& pool);
    void colour_constraints(const Model& m);
    void assign_slots();
    void prepare_constraints(const Model& m, const State& s, ThreadPool& pool);
    void prepare_context(const Model& m);
    // 4. impacts (contact_impacts.cpp)
    void impacts(const Model& m, State& s, ThreadPool& pool);
    void plan_impact_shifts(const Model& m, State& s);
    void apply_impact_shifts(State& s);
    // 5. substeps (contact_substeps.cpp)
    void substeps(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool);
    void free_flight(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool);
    void predict(const Model& m, State& s, ThreadPool& pool);
    void solve(State& s, ThreadPool& pool);
    void integrate_substep(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool);
    void relax(const Model& m, State& s, ThreadPool& pool);
    void follow_bodies(ThreadPool& pool);
    void sweep_constraints(State& s, ThreadPool& pool, bool use_bias);
    void track_motion(const Model& m, const State& s, ThreadPool& pool);
    void integrate_awake(const Model& m, State& s, IntegrateFn integrate, double h,
                         ThreadPool& pool);
    void integrate_all(const Model& m, State& s, IntegrateFn integrate, double h, ThreadPool& pool);
    // 6. store (contact_store.cpp)
    void store(State& s);
    // 7. sleep (contact_sleep.cpp)
    void sleep(const Model& m, State& s);

    template <class F>
    void for_each_colour(ThreadPool& pool, F&& fn);

    ContactStats stats_;
    ContactProfile profile_;
    double h_ = 0.0;

    // Per body.
    std::vector<ShapePose> pose_;
    std::vector<Aabb> box_;
    std::vector<double> plane_margin_;
    std::vector<std::uint8_t> awake_; // dynamic and not asleep
    std::vector<std::uint8_t> in_constraint_;
    SolverBodies bodies_;

    // Contacts found this step, becoming the State's cache at the end.
    BroadPhase broad_;
    std::vector<std::vector<std::uint64_t>> pairs_; // per worker
    std::vector<ContactCache> found_;               // per worker
    ContactCache next_;
    std::vector<std::uint64_t> old_keys_; // hash table of last step's pairs
    std::vector<int> old_slots_;
    int narrow_count_ = 0; // manifolds of next_ from the narrow phase

    // Constraints in colour order: colour c is manifolds_[colour_start_[c] .. [c + 1]).
    std::vector<SolverManifold> manifolds_;
    std::vector<SolverPoint> points_;
    std::vector<int> constraint_of_; // per manifold of next_: constraint or -1
    std::vector<int> colour_of_, colour_start_, point_start_, cursor_;
    std::vector<std::uint64_t> colour_bits_;
    int colour_count_ = 0;
    SolverContext ctx_; // the substep and the soft contact's coefficients
    int substeps_ = 1;
    int iterations_ = 1;       // solve sweeps per substep
    int relax_iterations_ = 1; // relax sweeps per substep

    // Bodies the substeps touch.
    std::vector<int> constrained_, sleeping_;
    std::vector<Vec3> solved_v_, before_x_, sleep_x_;
    std::vector<std::exception_ptr> integrate_errors_; // per worker
    std::vector<Quat> sleep_q_;
    std::vector<std::uint8_t> impact_flags_;
    std::vector<int> impact_count_, shifted_;
    std::vector<Vec3> shift_;

    // Islands (sleeping).
    std::vector<int> parent_, island_min_;
    std::vector<double> island_slow_;
};

template <class F>
void ContactStage::for_each_colour(ThreadPool& pool, F&& fn) {
    // Within a colour no two constraints share a moving body, so its constraints can be solved
    // in any order, or in parallel, with bit-identical results. Colours run in order.
    for (int c = 0; c < colour_count_; ++c) {
        const int begin = colour_start_[c], end = colour_start_[c + 1];
        if (c == kOverflow || end - begin < kColourGrain) {
            fn(begin, end, 0);
            continue;
        }
        pool.for_ranges(end - begin, kColourGrain,
                        [&](int b, int e, int worker) { fn(begin + b, begin + e, worker); });
    }
}

} // namespace tumble::physics
