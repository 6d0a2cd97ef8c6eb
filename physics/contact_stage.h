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

// What the solver spent in the last step (issue 28), over the islands it solved.
struct ContactEffort {
    int islands = 0;                        // islands solved
    int bodies = 0;                         // bodies in them
    int substeps_min = 0, substeps_max = 0; // over the islands
    double body_substeps = 0;               // sum over those bodies of their island's substeps
    double point_sweeps = 0; // sum over contact points of the sweeps that solved them
    int sweeps_max = 0;      // most solve plus relax sweeps of one island in one substep
    int capped_substeps = 0; // islands that asked for more than the most substeps (64)
    int capped_sweeps = 0;   // island solves or relaxes stopped at the most sweeps, unconverged
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
    ContactEffort effort;
};

// Wall time of the last step's stages, ms (Box2D's b2Profile).
struct ContactProfile {
    double broad = 0, narrow = 0, prepare = 0, impacts = 0, solve = 0, integrate = 0, finish = 0;
};

// The solver context of a step h split into `substeps`: the substep, the soft contact's
// coefficients at that substep (contact_effort.cpp).
SolverContext solver_context(const Model& m, double step_h, int substeps);

// Islands with the same substep count, stepped together (contact_effort.cpp): their constraints
// in colour order, the bodies in them, and the substep's solver context.
struct SubstepGroup {
    int substeps = 1;
    SolverContext ctx;
    std::vector<int> slots;  // constraints in colour order
    std::vector<int> starts; // colour c: slots[starts[c] .. starts[c + 1])
    std::vector<int> bodies; // the moving bodies of its constraints, ascending
    bool turns = false;      // some body turns its anchors (not a sphere): follow_bodies runs
    // The constraints of the islands that take a second (third) solve or relax sweep, in colour
    // order, and the contact points in each list.
    std::vector<int> solve2, solve2_starts, solve3, solve3_starts, relax2, relax2_starts;
    double points = 0, solve2_points = 0, solve3_points = 0, relax2_points = 0;
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
    // 5. substeps: the effort per island (contact_effort.cpp), then each group of islands with
    // the same substep count through its substeps (contact_substeps.cpp), swept until converged
    // (contact_sweeps.cpp)
    void plan_effort(const Model& m, const State& s);
    void plan_fixed_effort(const Model& m);
    void find_islands(const Model& m);
    void support_levels(const Model& m);
    void load_need(const Model& m, const State& s);
    void choose_effort(const Model& m, const State& s);
    void form_groups(const Model& m);
    void scale_warm_start(bool to_substep);
    void substeps(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool);
    void free_flight(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool);
    void predict(const Model& m, const State& s, ThreadPool& pool, const SubstepGroup& g);
    void solve(ThreadPool& pool, const SubstepGroup& g);
    void integrate_substep(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool,
                           const SubstepGroup& g);
    void relax(const Model& m, State& s, ThreadPool& pool, const SubstepGroup& g);
    void load_velocities(const State& s, ThreadPool& pool, const SubstepGroup& g);
    void store_velocities(State& s, ThreadPool& pool, const SubstepGroup& g);
    void follow_bodies(ThreadPool& pool, const SubstepGroup& g);
    void sweeps(ThreadPool& pool, const SubstepGroup& g, bool use_bias);
    void sweep_list(ThreadPool& pool, const SubstepGroup& g, const std::vector<int>& list,
                    const std::vector<int>& starts, bool use_bias);
    void track_motion(const Model& m, const State& s, ThreadPool& pool, const SubstepGroup& g);
    void integrate_awake(const Model& m, State& s, IntegrateFn integrate, double h,
                         ThreadPool& pool);
    void integrate_all(const Model& m, State& s, IntegrateFn integrate, double h,
                       std::span<const int> bodies, ThreadPool& pool);
    // 6. store (contact_store.cpp)
    void store(State& s);
    // 7. sleep (contact_sleep.cpp)
    void sleep(const Model& m, State& s);

    template <class F>
    void for_each_colour(ThreadPool& pool, F&& fn);
    template <class F>
    void for_each_listed(ThreadPool& pool, const std::vector<int>& list,
                         const std::vector<int>& starts, F&& fn);

    ContactStats stats_;
    ContactProfile profile_;
    double h_ = 0.0;

    // Per body.
    std::vector<ShapePose> pose_;
    std::vector<Aabb> box_;
    std::vector<double> plane_margin_;
    std::vector<Vec3> load_accel_;    // a = g s + F_applied / m (0 for a static body), m/s^2
    std::vector<std::uint8_t> awake_; // dynamic and not asleep
    std::vector<std::uint8_t> in_constraint_;
    SolverBodies bodies_;
    std::vector<SolverBody> solver_bodies_; // what the sweeps read and write, per body

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
    std::vector<PointAux> aux_; // per point of points_
    std::vector<int> colour_of_, colour_start_, point_start_, cursor_;
    std::vector<std::uint64_t> colour_bits_;
    int colour_count_ = 0;
    SolverContext ctx_; // the step's context (impacts); each group has its substep's own

    // Effort (contact_islands.cpp, contact_effort.cpp). Islands: bodies linked by constraints
    // between two moving bodies; each island's substep count decides its group.
    bool fixed_ = false; // fixed effort (ContactSettings::substeps/iterations)
    int fixed_iterations_ = 1, fixed_relax_ = 1;
    std::vector<int> island_of_body_; // per body: its island, -1 outside constraints
    std::vector<int> root_island_;    // per union-find root: its island
    std::vector<int> island_of_;      // per constraint (slot): its island
    std::vector<int> level_;          // per body: its support level (contact_islands.cpp)
    std::vector<int> adjacency_start_, adjacency_, adjacency_fill_, queue_;
    std::vector<int> island_top_, level_offset_, level_points_; // per island level
    std::vector<double> level_weight_, level_mass_;
    std::vector<double> island_need_;  // per island: substeps its loads and spin ask for
    std::vector<double> body_speed_;   // per body: its fastest point, m/s
    std::vector<int> island_substeps_; // per island: the substeps it gets (1 .. 64)
    std::vector<std::uint8_t> island_solve_, island_relax_; // per island: sweeps per substep
    std::vector<int> island_group_;                         // per island: its group
    std::vector<SubstepGroup> groups_;
    int group_count_ = 0;
    std::vector<int> free_; // awake dynamic bodies in no constraint

    // Bodies the substeps touch.
    std::vector<int> constrained_, sleeping_;
    std::vector<Vec3> solved_v_, before_x_, sleep_x_;
    std::vector<Vec3> predicted_v_, predicted_w_; // per group body: velocities before the solve
    std::vector<std::uint8_t> pushed_; // per group body: the solve changed its velocities
    std::vector<std::exception_ptr> integrate_errors_; // per worker
    std::vector<Quat> sleep_q_;
    std::vector<std::uint8_t> impact_flags_;
    // Impact sweeps (contact_impacts.cpp): when each body's velocity last changed and when each
    // constraint was last looked at, as sweep * constraints + slot.
    std::vector<std::int64_t> impact_changed_, impact_seen_;
    std::vector<int> impact_count_, shifted_;
    std::vector<Vec3> shift_;

    // Islands (sleeping).
    std::vector<int> parent_, island_min_;
    std::vector<double> island_slow_;
};

template <class F>
void ContactStage::for_each_listed(ThreadPool& pool, const std::vector<int>& list,
                                   const std::vector<int>& starts, F&& fn) {
    // The constraints list[starts[c] .. starts[c + 1]) of each colour c, as for_each_colour.
    for (int c = 0; c < colour_count_; ++c) {
        const int begin = starts[c], end = starts[c + 1];
        if (c == kOverflow || end - begin < kColourGrain) {
            for (int k = begin; k < end; ++k) fn(list[k], 0);
            continue;
        }
        pool.for_ranges(end - begin, kColourGrain, [&](int b, int e, int worker) {
            for (int k = begin + b; k < begin + e; ++k) fn(list[k], worker);
        });
    }
}

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
