// The grid broad phase finds exactly the pairs a brute-force test of every pair finds: bodies of
// mixed sizes (some "large"), static and sleeping ones, planes; each pair once.
#include "physics/broadphase.h"
#include "physics/build.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace tumble::physics {
namespace {

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
    const Model m = build_model({}, defs);
    State s;
    s.x.resize(defs.size()), s.q.resize(defs.size());
    for (std::size_t i = 0; i < defs.size(); ++i)
        s.x[i] = defs[i].position, s.q[i] = defs[i].orientation;
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
    BroadPhase bp;
    bp.build(m, box, awake);
    std::vector<std::uint64_t> found;
    bp.query(m, box, pose, plane_margin, 0, static_cast<int>(bp.queries().size()), found);
    const std::set<std::uint64_t> unique(found.begin(), found.end());
    EXPECT_EQ(unique.size(), found.size()) << "a pair was reported twice";

    std::set<std::uint64_t> expected;
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
                    expected.insert(pair_key(a, b));
                continue;
            }
            if (overlap(a, b)) expected.insert(pair_key(a, b));
        }
    EXPECT_EQ(unique, expected);
    std::printf("[measured] pairs %zu, cell %.3f m\n", expected.size(), bp.cell_size());
}

} // namespace
} // namespace tumble::physics
