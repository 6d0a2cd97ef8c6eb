// Contact stage, effort: what each island of bodies in contact gets this step (issue 28). An
// island is a set of moving bodies linked by contacts between two of them (contact_islands.cpp);
// islands do not touch, so each is solved with its own substeps and sweeps, and bodies in no
// constraint fly over the whole step. Decided at every step from the island as it is now, and
// counted in ContactStats::effort (`tumble explain`, the run summary).
//
// Substeps follow the contact tolerance d (ContactSettings::tolerance, world.contact_tolerance).
// The soft contact's stiffness follows the substep h' = h / n: its frequency is a quarter of the
// substep rate (twice that against a support: a static or sleeping body), and a contact carrying
// the force F sags into the other body by
//   sag = F / (m_eff omega^2),  omega = 2 pi hertz_fraction n / h  (x 2 against a support),
// so the island gets the fewest n with every contact's sag within d:
//   n >= h / (2 pi hertz_fraction k) sqrt(F / (m_eff d)),   k = 2 against a support, else 1,
// with F estimated from the island's weights and support levels, or for a quiet contact from its
// last impulse (contact_islands.cpp). A body that turns (anything but a sphere) also gets enough
// substeps to turn at most kTurnPerSubstep in one: its contact anchors follow it between substeps
// (the sharp top at 100 rad/s sank 2.2 mm at one substep of 0.42 rad, 0.7 mm at two, 0.024 mm at
// 0.1 rad). The count is the fewest whole n that does both, at most kMaxSubsteps. (Until
// 2026-11-28 it was the next power of two, which kept the State's per-step impulses exact when
// divided by n; it gave the 8000-sphere rain 1.3x the body-substeps the sag asks for, and the
// one-ulp rounding of a division by 3 or 5 does not matter to an impulse the next sweep changes.)
// The State holds each island's impulses per step (n times a substep's) and a substep starts from
// them divided by n, whatever the island's count was in the step before (scale_warm_start).
//
// Sweeps follow the island's constraints: one solve sweep for a body against supports only (one
// sweep solves a lone manifold) and where moving bodies meet at single points (spheres in a
// pile), two where they meet over several points (a box on a box: one sweep over the four
// corners, in turn, spreads the load unevenly, and a column of 10 boxes drifted 1.04 mm, over
// the stability map's 1 mm), three where their masses differ by more than kHeavyRatio (a 100 kg
// cube on a 1 kg one swayed 7 mm with two at 16 substeps, 0.02 mm with three); one relax sweep,
// two where a manifold has several points (one sweep over a box's four corners takes the
// push-out back unevenly and turns the box; docs/contacts.md). Two solve sweeps for single
// points too, as until 2026-11-28, made the 8000-sphere rain 1.28x slower (20.1 against 25.8
// steps/s) for a deepest overlap of 0.079 instead of 0.091 mm, both within the 0.1 mm tolerance.
// Convergence-driven sweeping was measured and not kept: stopping an island when a sweep changed
// its velocities by less than d / h spent 4.5 sweeps per contact in the sphere rain, where these
// counts then spent 3 for a smaller penetration (2.85 since single points take one solve sweep),
// and let the stacks stop after one relax sweep and walk 4 mm in 10 s (docs/contacts.md).
//
// Fixed effort (the scene set world.substeps or world.iterations): one group of every constraint
// with the scene's counts, every awake body integrated at each substep and the State's impulses
// per substep: the code path and the bits of the stage before effort on demand.
#include "physics/contact_stage.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tumble::physics {
namespace {

// The most substeps effort on demand gives an island (the scene format's limit for
// world.substeps); an island that asks for more gets these and is counted as capped.
constexpr int kMaxSubsteps = 64;
// Largest turn of a turning body in one substep, rad. Lesson 9's heavy tops (tips on a table,
// friction 1, 55-120 rad/s at h = 1/480 s) at 0.3 rad got one substep and lost 93% of L_3 and 90%
// of their energy in 6 s, the tip wandering 62 mm; at 0.1 rad (2-3 substeps) they keep E to 0.32%,
// L_3 to 3.7e-4 and the tip within 1.4 mm (fixed 1440 substeps per second: 0.28%, 1.6e-4, 1.4 mm;
// with power-of-two counts, 2-4 substeps: 0.23%, 1.9e-4, 1.0 mm).
constexpr double kTurnPerSubstep = 0.1;
// Longest substep of effort on demand, s: an island gets at least h / kLongestSubstep substeps
// (1 at the default h = 1/240 s). A ball bouncing at h = 1/60 s in one substep of 1/60 s missed its
// apexes e^2n h0 by 7.8% (1/120 s: 2.6%); with substeps of 1/240 s by 1.9% (1.1%; 0.8% at
// h = 1/240 s), ContactPhysics.BouncingBallApexesFollowE2n.
constexpr double kLongestSubstep = 1.0 / 240.0;
// Mass ratio across a contact between two moving bodies above which its island takes a third solve
// sweep.
constexpr double kHeavyRatio = 10.0;

int substeps_at_least(double need) {
    int n = 1;
    while (n < need && n < kMaxSubsteps) ++n;
    return n;
}

} // namespace

SolverContext solver_context(const Model& m, double step_h, int substeps) {
    const double h = step_h / substeps;
    SolverContext ctx;
    const double hertz = m.contact.contact_hertz_fraction / h;
    const double zeta = m.contact.contact_damping_ratio;
    ctx.soft = make_softness(hertz, zeta, h);
    ctx.soft_static = make_softness(2.0 * hertz, zeta, h);
    ctx.h = h;
    ctx.inv_h = 1.0 / h;
    ctx.step_h = step_h;
    ctx.max_push_speed = m.contact.max_push_speed;
    ctx.restitution_threshold = m.contact.restitution_threshold;
    return ctx;
}

void ContactStage::plan_effort(const Model& m, const State& s) {
    stats_.effort = {};
    fixed_ = fixed_effort(m.contact);
    if (fixed_) return plan_fixed_effort(m);
    find_islands(m);   // contact_islands.cpp
    support_levels(m); // contact_islands.cpp
    choose_effort(m, s);
    form_groups(m);
    scale_warm_start(true);
}

void ContactStage::plan_fixed_effort(const Model& m) {
    const int constraints = static_cast<int>(manifolds_.size());
    fixed_iterations_ = iteration_count(m.contact);
    fixed_relax_ = m.contact.relax_iterations;
    group_count_ = 1;
    if (groups_.empty()) groups_.resize(1);
    SubstepGroup& g = groups_[0];
    g.substeps = substep_count(m.contact, h_);
    g.ctx = solver_context(m, h_, g.substeps);
    g.slots.resize(constraints);
    for (int c = 0; c < constraints; ++c) g.slots[c] = c;
    g.starts.assign(colour_start_.begin(), colour_start_.begin() + colour_count_ + 1);
    g.bodies = constrained_;
    g.turns = false;
    for (int i : constrained_) g.turns |= bodies_.rotates[i] != 0;
    island_of_.assign(constraints, 0);
    island_substeps_.assign(1, g.substeps);
    free_.clear();
    ContactEffort& e = stats_.effort;
    e.islands = 1;
    e.bodies = static_cast<int>(constrained_.size());
    e.substeps_min = e.substeps_max = g.substeps;
    e.body_substeps = double(e.bodies) * g.substeps;
    e.sweeps_max = fixed_iterations_ + fixed_relax_;
}

// Each island's substeps (the sag its loads ask for, contact_islands.cpp, and its bodies' spin)
// and sweeps (from its constraints), and the effort counted for the step's statistics.
void ContactStage::choose_effort(const Model& m, const State& s) {
    const int islands = stats_.effort.islands;
    island_need_.assign(islands, std::max(1.0, h_ / kLongestSubstep - 1e-9));
    load_need(m, s); // contact_islands.cpp
    island_solve_.assign(islands, 1);
    island_relax_.assign(islands, 1);
    for (std::size_t k = 0; k < manifolds_.size(); ++k) {
        const SolverManifold& c = manifolds_[k];
        const int island = island_of_[k];
        if (c.count > 1) island_relax_[island] = 2;
        if (!c.move_a || !c.move_b) continue;
        const double ratio = std::max(m.mass[c.a] * m.inv_mass[c.b], m.mass[c.b] * m.inv_mass[c.a]);
        const std::uint8_t sweeps = ratio > kHeavyRatio ? 3 : c.count > 1 ? 2 : 1;
        island_solve_[island] = std::max(island_solve_[island], sweeps);
    }
    for (int i : constrained_) {
        if (!bodies_.rotates[i]) continue;
        double& need = island_need_[island_of_body_[i]];
        need = std::max(need, s.w[i].norm() * h_ / kTurnPerSubstep);
    }
    island_substeps_.resize(islands);
    ContactEffort& e = stats_.effort;
    e.substeps_min = islands > 0 ? kMaxSubsteps : 0;
    for (int i = 0; i < islands; ++i) {
        island_substeps_[i] = substeps_at_least(island_need_[i]);
        e.capped_substeps += island_need_[i] > kMaxSubsteps;
        e.substeps_min = std::min(e.substeps_min, island_substeps_[i]);
        e.substeps_max = std::max(e.substeps_max, island_substeps_[i]);
        e.sweeps_max = std::max(e.sweeps_max, island_solve_[i] + island_relax_[i]);
    }
    for (int i : constrained_) e.body_substeps += island_substeps_[island_of_body_[i]];
}

// One group per substep count in use, fewest substeps first; each holds its islands' constraints
// in colour order (and those of its islands that take second sweeps) and their bodies in
// ascending order. Bodies in no constraint fly freely.
void ContactStage::form_groups(const Model& m) {
    int used[kMaxSubsteps + 1] = {}; // substep counts 1 .. kMaxSubsteps in use
    for (int n : island_substeps_) used[n] = 1;
    int group_of_count[kMaxSubsteps + 1];
    group_count_ = 0;
    for (int k = 0; k <= kMaxSubsteps; ++k) group_of_count[k] = used[k] ? group_count_++ : -1;
    if (static_cast<int>(groups_.size()) < group_count_) groups_.resize(group_count_);
    for (int k = 0; k <= kMaxSubsteps; ++k) {
        if (group_of_count[k] < 0) continue;
        SubstepGroup& g = groups_[group_of_count[k]];
        g.substeps = k;
        g.ctx = solver_context(m, h_, g.substeps);
        g.slots.clear(), g.solve2.clear(), g.solve3.clear(), g.relax2.clear(), g.bodies.clear();
        for (std::vector<int>* v :
             {&g.starts, &g.solve2_starts, &g.solve3_starts, &g.relax2_starts})
            v->assign(colour_count_ + 1, 0);
        g.points = g.solve2_points = g.solve3_points = g.relax2_points = 0;
    }
    island_group_.resize(island_substeps_.size());
    for (std::size_t i = 0; i < island_substeps_.size(); ++i)
        island_group_[i] = group_of_count[island_substeps_[i]];
    for (int col = 0; col < colour_count_; ++col) {
        for (int c = colour_start_[col]; c < colour_start_[col + 1]; ++c) {
            const int island = island_of_[c];
            SubstepGroup& g = groups_[island_group_[island]];
            const int points = manifolds_[c].count;
            g.slots.push_back(c), g.points += points;
            if (island_solve_[island] > 1) g.solve2.push_back(c), g.solve2_points += points;
            if (island_solve_[island] > 2) g.solve3.push_back(c), g.solve3_points += points;
            if (island_relax_[island] > 1) g.relax2.push_back(c), g.relax2_points += points;
        }
        for (int k = 0; k < group_count_; ++k) {
            SubstepGroup& g = groups_[k];
            g.starts[col + 1] = static_cast<int>(g.slots.size());
            g.solve2_starts[col + 1] = static_cast<int>(g.solve2.size());
            g.solve3_starts[col + 1] = static_cast<int>(g.solve3.size());
            g.relax2_starts[col + 1] = static_cast<int>(g.relax2.size());
        }
    }
    for (int k = 0; k < group_count_; ++k) groups_[k].turns = false;
    for (int i : constrained_) {
        SubstepGroup& g = groups_[island_group_[island_of_body_[i]]];
        g.bodies.push_back(i);
        g.turns |= bodies_.rotates[i] != 0;
    }
    free_.clear();
    for (int i : m.dynamic_bodies)
        if (awake_[i] && !in_constraint_[i]) free_.push_back(i);
}

// The State's impulses are per step; a substep's are 1/n of them (rounded once; exact when n is a
// power of two).
void ContactStage::scale_warm_start(bool to_substep) {
    for (std::size_t k = 0; k < manifolds_.size(); ++k) {
        const SolverManifold& c = manifolds_[k];
        const double n = island_substeps_[island_of_[k]];
        for (int j = 0; j < c.count; ++j) {
            SolverPoint& p = points_[c.first + j];
            for (double* x : {&p.normal_impulse, &p.friction_impulse[0], &p.friction_impulse[1]})
                *x = to_substep ? *x / n : *x * n;
        }
    }
}

} // namespace tumble::physics
