// Contact stage, sweeps: the Gauss-Seidel sweeps of one substep's solve or relax over a group of
// islands (contact_effort.cpp), colour by colour.
//
// Fixed effort sweeps every constraint `iterations` times (solve) and `relax_iterations` times
// (relax). Effort on demand gives each island its own counts (contact_effort.cpp: one or two
// solve sweeps, one or two relax sweeps): sweep k visits the constraints of the islands that take
// at least k, in colour order, so an island with one sweep leaves the list after the first.
//
// Determinism: the lists keep colour order and depend only on the islands, not on the threads.
#include "physics/contact_stage.h"

#include <algorithm>

namespace tumble::physics {

void ContactStage::sweeps(ThreadPool& pool, const SubstepGroup& g, bool use_bias) {
    ContactEffort& e = stats_.effort;
    if (fixed_) {
        const int count = use_bias ? fixed_iterations_ : fixed_relax_;
        for (int k = 0; k < count; ++k) sweep_list(pool, g, g.slots, g.starts, use_bias);
        e.point_sweeps += double(count) * points_.size();
        return;
    }
    sweep_list(pool, g, g.slots, g.starts, use_bias);
    e.point_sweeps += g.points;
    const std::vector<int>& second = use_bias ? g.solve2 : g.relax2;
    if (second.empty()) return;
    sweep_list(pool, g, second, use_bias ? g.solve2_starts : g.relax2_starts, use_bias);
    e.point_sweeps += use_bias ? g.solve2_points : g.relax2_points;
    if (!use_bias || g.solve3.empty()) return;
    sweep_list(pool, g, g.solve3, g.solve3_starts, use_bias);
    e.point_sweeps += g.solve3_points;
}

// One sweep over the listed constraints, colour by colour.
void ContactStage::sweep_list(ThreadPool& pool, const SubstepGroup& g, const std::vector<int>& list,
                              const std::vector<int>& starts, bool use_bias) {
    for_each_listed(pool, list, starts, [&](int c, int) {
        solve_manifold(manifolds_[c], &points_[manifolds_[c].first], g.ctx, use_bias,
                       solver_bodies_.data());
    });
}

} // namespace tumble::physics
