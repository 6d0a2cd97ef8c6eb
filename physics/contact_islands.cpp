// Contact stage, islands: the moving bodies linked by this step's constraints, and how each island
// stands on its supports (issue 28: the effort per island, contact_effort.cpp, follows from it).
//
// An island is a set of moving bodies linked by contacts between two of them; a body against
// static (or sleeping) bodies only is an island of its own. Islands are found by union-find over
// the constraints and numbered in the order of their smallest body, so the same for any thread
// count.
//
// Support levels. A body touching a static or sleeping body is on level 1, a body touching a level
// 1 body is on level 2, and so on (breadth first over the island's constraints); a body of an
// island with no support has level 0 (it is in flight: nothing holds a load). The contacts between
// level l and level l + 1 (level 0: the supports) carry, at rest, the weight of every body above
// them, W(>= l + 1) = sum of m |F / m| over the island's bodies on levels l + 1 and up, shared by
// their touching points: the load of one point is estimated as W(>= l + 1) / P(l). Exact for a
// column (a tower of boxes puts the weight of the n - l boxes above on the four corners at level
// l), the mean for a pile. An estimate from the island's weights, not from the impulses of the
// last step: those also hold the momentum of every collision, which in a sphere rain's first
// second asked for 16 to 64 substeps of stiffness that changed nothing (docs/contacts.md).
#include "physics/can_touch.h"
#include "physics/contact_stage.h"
#include "physics/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tumble::physics {

void ContactStage::find_islands(const Model& m) {
    const int n = m.body_count();
    parent_.resize(n);
    for (int i = 0; i < n; ++i) parent_[i] = i;
    for (const SolverManifold& c : manifolds_)
        if (c.move_a && c.move_b) parent_[union_root(parent_, c.a)] = union_root(parent_, c.b);
    island_of_body_.assign(n, -1);
    root_island_.assign(n, -1);
    int islands = 0;
    for (int i : constrained_) {
        const int r = union_root(parent_, i);
        if (root_island_[r] < 0) root_island_[r] = islands++;
        island_of_body_[i] = root_island_[r];
    }
    const int constraints = static_cast<int>(manifolds_.size());
    island_of_.resize(constraints);
    for (int k = 0; k < constraints; ++k) {
        const SolverManifold& c = manifolds_[k];
        island_of_[k] = island_of_body_[c.move_a ? c.a : c.b];
    }
    stats_.effort.islands = islands;
    stats_.effort.bodies = static_cast<int>(constrained_.size());
}

// Levels by breadth-first search from the bodies that touch a support, over an adjacency list of
// the constraints between two moving bodies (compressed rows by body).
void ContactStage::support_levels(const Model& m) {
    const int n = m.body_count();
    level_.assign(n, 0);
    adjacency_start_.assign(n + 1, 0);
    for (const SolverManifold& c : manifolds_)
        if (c.move_a && c.move_b) ++adjacency_start_[c.a + 1], ++adjacency_start_[c.b + 1];
    for (int i = 0; i < n; ++i) adjacency_start_[i + 1] += adjacency_start_[i];
    adjacency_.resize(adjacency_start_[n]);
    adjacency_fill_.assign(adjacency_start_.begin(), adjacency_start_.end() - 1);
    queue_.clear();
    for (const SolverManifold& c : manifolds_) {
        if (c.move_a && c.move_b) {
            adjacency_[adjacency_fill_[c.a]++] = c.b;
            adjacency_[adjacency_fill_[c.b]++] = c.a;
            continue;
        }
        const int i = c.move_a ? c.a : c.b; // against a support
        if (level_[i] == 0) level_[i] = 1, queue_.push_back(i);
    }
    for (std::size_t k = 0; k < queue_.size(); ++k) {
        const int i = queue_[k];
        for (int j = adjacency_start_[i]; j < adjacency_start_[i + 1]; ++j) {
            const int o = adjacency_[j];
            if (level_[o] == 0) level_[o] = level_[i] + 1, queue_.push_back(o);
        }
    }
}

// The substeps each island's loads ask for (see contact_effort.cpp for the sag): the larger of
// two estimates of each contact's force. From the support levels, W(>= l + 1) / P(l) (the top of
// this file). And, for a quiet contact (both bodies slower than tolerance / h at every point, so
// that nothing but a load changes its impulse), its last step's impulse over h: the loads of a
// pile's force chains, which the level estimate puts at their mean (a sphere at the bottom of the
// 8000-sphere rain carries up to 20 N where the mean is 6 N).
void ContactStage::load_need(const Model& m, const State& s) {
    const int islands = stats_.effort.islands;
    // Per island, its levels 0 .. top at level_offset_[i] + l.
    island_top_.assign(islands, 0);
    for (int i : constrained_)
        island_top_[island_of_body_[i]] = std::max(island_top_[island_of_body_[i]], level_[i]);
    level_offset_.resize(islands + 1);
    level_offset_[0] = 0;
    for (int i = 0; i < islands; ++i) level_offset_[i + 1] = level_offset_[i] + island_top_[i] + 2;
    const int slots = level_offset_[islands];
    level_weight_.assign(slots, 0.0);
    level_points_.assign(slots, 0);
    level_mass_.assign(slots, std::numeric_limits<double>::infinity());
    body_speed_.resize(m.body_count());
    for (int i : constrained_) {
        level_weight_[level_offset_[island_of_body_[i]] + level_[i]] +=
            m.mass[i] * bodies_.accel[i].norm();
        body_speed_[i] = std::max(s.v[i].norm(), s.w[i].norm() * bounding_radius(m, i));
    }
    for (int i = 0; i < islands; ++i) // W(>= l): the weight on level l and above
        for (int l = level_offset_[i + 1] - 2; l > level_offset_[i]; --l)
            level_weight_[l] += level_weight_[l + 1];
    const double tolerance = m.contact.tolerance, quiet = tolerance / h_;
    // n = scale / k sqrt(F / (m_eff d)), k = 2 against a support (contact_effort.cpp)
    const double scale = h_ / (2.0 * std::numbers::pi * m.contact.contact_hertz_fraction);
    auto need = [&](double force, double mass, bool support) {
        return scale / (support ? 2.0 : 1.0) * std::sqrt(force / (mass * tolerance));
    };
    for (std::size_t k = 0; k < manifolds_.size(); ++k) {
        const SolverManifold& c = manifolds_[k];
        const int island = island_of_[k];
        const bool support = !c.move_a || !c.move_b;
        if ((!c.move_a || body_speed_[c.a] <= quiet) && (!c.move_b || body_speed_[c.b] <= quiet))
            for (int j = 0; j < c.count; ++j) {
                const SolverPoint& p = points_[c.first + j];
                if (p.normal_impulse <= 0.0) continue;
                // The State holds impulses per step (contact_effort.cpp).
                island_need_[island] = std::max(
                    island_need_[island], need(p.normal_impulse / h_, p.normal_mass, support));
            }
        const int la = c.move_a ? level_[c.a] : 0, lb = c.move_b ? level_[c.b] : 0;
        if (la + lb == 0 || (la != lb + 1 && lb != la + 1)) continue; // in flight, or side by side
        const int slot = level_offset_[island] + std::min(la, lb);
        for (int j = 0; j < c.count; ++j) {
            const SolverPoint& p = points_[c.first + j];
            if (aux_[c.first + j].separation0 > tolerance)
                continue; // not touching: carries nothing
            ++level_points_[slot];
            level_mass_[slot] = std::min(level_mass_[slot], p.normal_mass);
        }
    }
    for (int i = 0; i < islands; ++i)
        for (int l = level_offset_[i]; l + 1 < level_offset_[i + 1]; ++l)
            if (level_points_[l] > 0)
                island_need_[i] =
                    std::max(island_need_[i], need(level_weight_[l + 1] / level_points_[l],
                                                   level_mass_[l], l == level_offset_[i]));
}

} // namespace tumble::physics
