#include "physics/overlaps.h"

#include "physics/build_contacts.h"
#include "physics/collide.h"

#include <algorithm>
#include <numeric>

namespace tumble::physics {
namespace {

double deepest(const Manifold& m) {
    double d = 0.0;
    for (int k = 0; k < m.count; ++k) d = std::min(d, m.points[k].separation);
    return -d;
}

} // namespace

std::vector<Overlap> find_overlaps(const Model& m, const State& s, double min_depth,
                                   bool statics_only) {
    const int n = m.body_count();
    std::vector<ShapePose> pose(n);
    std::vector<Aabb> box(n);
    std::vector<int> bounded, planes;
    for (int i = 0; i < n; ++i) {
        pose[i] = shape_pose(m, s.x[i], s.q[i], i);
        if (m.shape[i].kind == ShapeKind::Plane) {
            planes.push_back(i);
        } else {
            box[i] = shape_aabb(m, i, pose[i]);
            bounded.push_back(i);
        }
    }
    auto wanted = [&](int a, int b) {
        const bool both_static = !m.is_dynamic(a) && !m.is_dynamic(b);
        return statics_only ? both_static : !both_static;
    };
    std::vector<Overlap> out;
    Manifold man;
    auto test = [&](int a, int b) {
        if (a > b) std::swap(a, b);
        if (!wanted(a, b)) return;
        collide(m, a, pose[a], b, pose[b], 0.0, man);
        const double depth = deepest(man);
        if (depth > min_depth) out.push_back({a, b, depth});
    };
    // Sweep and prune along x: sort by the lower bound, compare while the intervals overlap.
    std::stable_sort(bounded.begin(), bounded.end(),
                     [&](int a, int b) { return box[a].lo.x() < box[b].lo.x(); });
    for (std::size_t i = 0; i < bounded.size(); ++i) {
        const Aabb& bi = box[bounded[i]];
        for (std::size_t j = i + 1; j < bounded.size() && box[bounded[j]].lo.x() <= bi.hi.x();
             ++j) {
            const Aabb& bj = box[bounded[j]];
            if ((bi.lo.array() <= bj.hi.array()).all() && (bj.lo.array() <= bi.hi.array()).all())
                test(bounded[i], bounded[j]);
        }
    }
    for (int p : planes)
        for (int i : bounded) test(p, i);
    std::sort(out.begin(), out.end(), [](const Overlap& x, const Overlap& y) {
        return std::tie(x.a, x.b) < std::tie(y.a, y.b);
    });
    return out;
}

std::vector<Overlap> deep_initial_overlaps(const Model& m, const State& s) {
    std::vector<Overlap> out;
    for (const Overlap& o : find_overlaps(m, s, 0.0, false)) {
        const double thin = std::min(shape_thickness(m, o.a), shape_thickness(m, o.b));
        if (o.depth > std::min(0.01, 0.2 * thin)) out.push_back(o);
    }
    return out;
}

void check_static_overlaps(const Model& m, const State& s) {
    const auto overlaps = find_overlaps(m, s, 0.001, true);
    if (overlaps.empty()) return;
    const Overlap& o = overlaps.front();
    throw ModelError(o.b, "position",
                     "static body " + std::to_string(o.b) + " overlaps static body " +
                         std::to_string(o.a) + " by " + std::to_string(o.depth * 1000.0) +
                         " mm; static shapes never move, so this is almost certainly a mistake "
                         "(move them apart or make one of them dynamic)");
}

} // namespace tumble::physics
