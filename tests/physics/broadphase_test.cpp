// The grid broad phase finds exactly the pairs a brute-force test of every pair finds: bodies of
// mixed sizes (some "large"), static and sleeping ones, planes; each pair once.
#include "physics/broadphase.h"
#include "physics/build.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

namespace tumble::physics {
namespace {

// The pairs the broad phase reports for bodies `defs` placed as given, or at `at` where given
// (positions no model accepts: NaN, infinity), with every dynamic body awake but every 7th, and
// the pairs a brute-force test of every pair finds.
struct Pairs {
    std::vector<std::uint64_t> found;
    std::set<std::uint64_t> expected;
    BroadPhase bp;
};

Pairs find_pairs(const std::vector<BodyDef>& defs, const std::vector<Vec3>& at = {}) {
    const Model m = build_model({}, defs);
    State s;
    s.x.resize(defs.size()), s.q.resize(defs.size());
    for (std::size_t i = 0; i < defs.size(); ++i)
        s.x[i] = i < at.size() ? at[i] : defs[i].position, s.q[i] = defs[i].orientation;
    const int n = m.body_count();
    std::vector<ShapePose> pose(n);
    std::vector<Aabb> box(n);
    std::vector<std::uint8_t> awake(n);
    std::vector<double> plane_margin(n, 0.05);
    for (int i = 0; i < n; ++i) {
        pose[i] = shape_pose(m, s.x[i], s.q[i], i);
        if (m.shape[i].kind != ShapeKind::Plane) box[i] = shape_aabb(m, i, pose[i]);
        awake[i] = m.is_dynamic(i) && i % 7 != 3; // some dynamic bodies asleep
    }
    Pairs p;
    p.bp.build(m, box, awake);
    p.bp.query(m, box, pose, plane_margin, 0, static_cast<int>(p.bp.queries().size()), p.found);

    auto overlap = [&](int a, int b) {
        return (box[a].lo.array() <= box[b].hi.array()).all() &&
               (box[b].lo.array() <= box[a].hi.array()).all();
    };
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b) {
            const bool a_queries = awake[a], b_queries = awake[b];
            if (!a_queries && !b_queries) continue; // nobody awake looks
            if (m.shape[a].kind == ShapeKind::Plane || m.shape[b].kind == ShapeKind::Plane) {
                const int body = m.shape[a].kind == ShapeKind::Plane ? b : a;
                const int plane = body == a ? b : a;
                const Vec3 nrm = pose[plane].rotation.col(2);
                if (plane_clearance(m, body, pose[body], nrm, nrm.dot(pose[plane].position)) <=
                    plane_margin[body])
                    p.expected.insert(pair_key(a, b));
                continue;
            }
            if (overlap(a, b)) p.expected.insert(pair_key(a, b));
        }
    return p;
}

void expect_brute_force(const Pairs& p) {
    const std::set<std::uint64_t> unique(p.found.begin(), p.found.end());
    EXPECT_EQ(unique.size(), p.found.size()) << "a pair was reported twice";
    EXPECT_EQ(unique, p.expected);
}

BodyDef sphere_at(double r, const Vec3& x) {
    BodyDef b;
    b.shape = Shape::sphere(r);
    b.position = x;
    return b;
}

TEST(BroadPhase, MatchesBruteForce) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pos(-3.0, 3.0), size(0.05, 0.3);
    std::vector<BodyDef> defs;
    BodyDef floor;
    floor.shape = Shape::plane();
    floor.motion = Motion::Static;
    defs.push_back(floor);
    for (int i = 0; i < 400; ++i) {
        BodyDef b;
        const int kind = i % 4;
        if (kind == 0) b.shape = Shape::sphere(size(rng));
        if (kind == 1) b.shape = Shape::box(Vec3(size(rng), size(rng), size(rng)));
        if (kind == 2) b.shape = Shape::capsule(size(rng), size(rng));
        if (kind == 3) b.shape = Shape::sphere(0.5 * size(rng));
        if (i % 50 == 7) b.shape = Shape::box(Vec3(2.0, 0.1, 0.1)); // large
        b.position = Vec3(pos(rng), pos(rng), 0.5 * pos(rng) + 1.5);
        b.orientation = Quat(Eigen::AngleAxisd(pos(rng), Vec3(pos(rng), pos(rng), 1).normalized()));
        if (i % 9 == 0) b.motion = Motion::Static;
        defs.push_back(b);
    }
    const Pairs p = find_pairs(defs);
    expect_brute_force(p);
    EXPECT_EQ(p.bp.outside_grid(), 0);
    std::printf("[measured] pairs %zu, cell %.3f m\n", p.expected.size(), p.bp.cell_size());
}

// Issue 32: a cell index beyond 32 bits was undefined behaviour (UBSan: signed overflow in the
// neighbour loop). The rule: a body more than 2^30 cells from the origin has no cell and is
// tested like a large body, so overlapping pairs far away, and pairs straddling the range's edge,
// are still found, exactly as brute force finds them.
TEST(BroadPhase, BodiesBeyondTheGridsRangeStillMeetTheirPartners) {
    std::vector<BodyDef> defs;
    for (int i = 0; i < 6; ++i) // a small cluster at the origin: the cell is its 2 r = 0.2 m
        defs.push_back(sphere_at(0.1, Vec3(0.15 * i, 0, 1)));
    // Smaller spheres (2 r = 0.1 m, boxes rounded at most 1e-4 m larger) in overlapping pairs
    // 0.08 m apart: far away (at 1e300 the two centres round to one), and one pair straddling
    // the range's edge, 0.2 cells inside and 0.2 cells outside.
    const double cell = 0.2, edge = BroadPhase::kGridRange * cell;
    for (const double x : {1e12, -1e12, 1e300, -1e300}) {
        defs.push_back(sphere_at(0.05, Vec3(x, 0, 0)));
        defs.push_back(sphere_at(0.05, Vec3(x + 0.08, 0, 0)));
    }
    defs.push_back(sphere_at(0.05, Vec3(edge - 0.04, 0, 0)));
    defs.push_back(sphere_at(0.05, Vec3(edge + 0.04, 0, 0)));
    const Pairs p = find_pairs(defs);
    EXPECT_NEAR(p.bp.cell_size(), cell, 1e-12); // the cluster's box, to rounding
    expect_brute_force(p);
    EXPECT_EQ(p.expected.size(), 5u + 4u + 1u); // the cluster's neighbours, far pairs, the edge
    EXPECT_EQ(p.bp.outside_grid(), 9);          // the eight far bodies and the one just outside
}

// A body whose box is not finite (NaN or infinite: a diverging run, or the error estimate's shadow
// of one) meets nothing, and the rest still meet each other.
TEST(BroadPhase, ABodyWithANonFiniteBoxMeetsNothing) {
    std::vector<BodyDef> defs;
    std::vector<Vec3> at;
    for (int i = 0; i < 7; ++i) {
        defs.push_back(sphere_at(0.1, Vec3(0.15 * i, 0, 1)));
        at.push_back(defs.back().position);
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    at[4] = Vec3(nan, 0, 1), at[5] = Vec3(0, inf, 1), at[6] = Vec3(0.05, 0, -inf);
    const Pairs p = find_pairs(defs, at);
    expect_brute_force(p);
    EXPECT_EQ(p.expected.size(), 3u);
    for (const std::uint64_t k : p.found) {
        EXPECT_LT(k >> 32, 4u);
        EXPECT_LT(k & 0xffffffffu, 4u);
    }
}

} // namespace
} // namespace tumble::physics
