// Contact stage, find: which bodies touch. Poses and swept bounding boxes, the broad phase, the
// narrow phase with warm-start matching against last step's contacts, and contacts of sleeping
// bodies carried over unchanged (they have not moved, so their manifolds are still exact).
#include "physics/contact_stage.h"
#include "physics/forces.h"

#include <cmath>
#include <limits>

namespace tumble::physics {
namespace {

constexpr std::uint64_t kEmpty = std::numeric_limits<std::uint64_t>::max();

std::uint32_t slot_hash(std::uint64_t key) {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL; // MurmurHash3's 64-bit finaliser
    key ^= key >> 33;
    return static_cast<std::uint32_t>(key);
}

// Speculative margin of a pair: how far the gap can close in one step, and the base distance for
// what that does not predict (the impulses of the step's other contacts). The relative centre
// moves by h u + 1/2 h^2 a (u = vB - vA, a = aB - aA from the loads, constant over the step), and
// rotation sweeps surface points up to `swing` from the centre, so the gap closes by at most
//   h (|u| + |wA| swingA + |wB| swingB) + 1/2 h^2 |a|.
// Without the last term a ball falling onto the floor at h = 1/30 s could sink g h^2 / 2 = 5.4 mm
// minus the base distance before its first contact.
// `accel`: per body, a = g s + F_applied / m from its loads (0 for a static body).
double pair_margin(const Model& m, const State& s, const std::vector<Vec3>& accel, int a, int b,
                   double h) {
    const double rel = (s.v[b] - s.v[a]).norm();
    const double spin = s.w[a].norm() * m.swing[a] + s.w[b].norm() * m.swing[b];
    const double loads = (accel[b] - accel[a]).norm();
    return m.contact.speculative_distance + h * (rel + spin) + 0.5 * h * h * loads;
}

// Last step's impulses at the point of manifold `o` (-1: none) with p's feature id, if any.
void carry_impulses(const ContactCache& old, int o, CachedPoint& p) {
    for (int j = 0; o >= 0 && j < old.count[o]; ++j) {
        const CachedPoint& q = old.points[old.first[o] + j];
        if (q.id == p.id) {
            p.normal_impulse = q.normal_impulse;
            p.friction_impulse = q.friction_impulse;
            break;
        }
    }
}

} // namespace

void ContactStage::find(const Model& m, const State& s, ThreadPool& pool) {
    Stopwatch clock;
    sweep_bounds(m, s, pool);
    const double poses = clock.lap();
    broad_phase(m, pool);
    profile_.broad = clock.lap();
    profile_.broad += poses;
    index_old_contacts(s.contacts);
    narrow_phase(m, s, pool);
    merge_found(s.contacts);
    profile_.narrow = clock.lap();
}

void ContactStage::sweep_bounds(const Model& m, const State& s, ThreadPool& pool) {
    const int n = m.body_count();
    pose_.resize(n);
    box_.resize(n);
    plane_margin_.resize(n);
    load_accel_.resize(n);
    awake_.resize(n);
    pool.for_ranges(n, 256, [&](int begin, int end, int) {
        for (int i = begin; i < end; ++i) {
            const bool dynamic = m.is_dynamic(i);
            awake_[i] = dynamic && !s.sleep.asleep[i];
            pose_[i] = shape_pose(m, s.x[i], s.q[i], i);
            load_accel_[i] = dynamic ? Vec3(m.inv_mass[i] * net_force(m, i)) : Vec3::Zero();
            // Grow the box by half the base margin and by the distance the body can move (its
            // terms of pair_margin: the boxes of a pair within its margin overlap).
            const double reach = dynamic ? h_ * (s.v[i].norm() + s.w[i].norm() * m.swing[i]) +
                                               0.5 * h_ * h_ * load_accel_[i].norm()
                                         : 0.0;
            plane_margin_[i] = m.contact.speculative_distance + reach;
            if (m.shape[i].kind == ShapeKind::Plane) continue;
            const Aabb b = shape_aabb(m, i, pose_[i]);
            const Vec3 grow = Vec3::Constant(0.5 * m.contact.speculative_distance + reach);
            box_[i] = {b.lo - grow, b.hi + grow};
        }
    });
}

void ContactStage::broad_phase(const Model& m, ThreadPool& pool) {
    broad_.build(m, box_, awake_);
    const int workers = pool.size();
    pairs_.resize(workers);
    found_.resize(workers);
    const int queries = static_cast<int>(broad_.queries().size());
    pool.run([&](int worker) {
        int begin, end;
        ThreadPool::range(queries, workers, worker, begin, end);
        pairs_[worker].clear();
        broad_.query(m, box_, pose_, plane_margin_, begin, end, pairs_[worker]);
    });
}

// Last step's manifolds by pair key (open addressing, at most half full).
void ContactStage::index_old_contacts(const ContactCache& old) {
    std::uint32_t size = 16;
    while (size < 2u * static_cast<std::uint32_t>(old.size())) size <<= 1;
    old_keys_.assign(size, kEmpty);
    old_slots_.resize(size);
    for (int k = 0; k < old.size(); ++k) {
        std::uint32_t slot = slot_hash(old.pair[k]) & (size - 1);
        while (old_keys_[slot] != kEmpty) slot = (slot + 1) & (size - 1);
        old_keys_[slot] = old.pair[k];
        old_slots_[slot] = k;
    }
}

int ContactStage::old_manifold(std::uint64_t key) const {
    const std::uint32_t size = static_cast<std::uint32_t>(old_keys_.size());
    std::uint32_t slot = slot_hash(key) & (size - 1);
    while (old_keys_[slot] != kEmpty) {
        if (old_keys_[slot] == key) return old_slots_[slot];
        slot = (slot + 1) & (size - 1);
    }
    return -1;
}

void ContactStage::narrow_phase(const Model& m, const State& s, ThreadPool& pool) {
    const ContactCache& old = s.contacts;
    pool.run([&](int worker) {
        const std::vector<std::uint64_t>& pairs = pairs_[worker];
        ContactCache& out = found_[worker];
        out.clear();
        Manifold man;
        for (std::uint64_t key : pairs) {
            const int a = pair_first(key), b = pair_second(key);
            collide(m, a, pose_[a], b, pose_[b], pair_margin(m, s, load_accel_, a, b, h_), man);
            if (man.count == 0) continue;
            const int o = old_manifold(key);
            out.pair.push_back(key);
            out.normal.push_back(man.normal);
            out.first.push_back(static_cast<int>(out.points.size()));
            out.count.push_back(man.count);
            for (int k = 0; k < man.count; ++k) {
                CachedPoint p{man.points[k].point, man.points[k].separation, man.points[k].id, 0.0,
                              Vec3::Zero()};
                carry_impulses(old, o, p);
                out.points.push_back(p);
            }
        }
    });
}

// Merge in worker order (the order a single thread would produce), then carry over the manifolds
// of pairs that no awake body looked at: both bodies asleep or static.
void ContactStage::merge_found(const ContactCache& old) {
    next_.clear();
    stats_.pairs = 0;
    auto append = [&](const ContactCache& from, int k) {
        next_.pair.push_back(from.pair[k]);
        next_.normal.push_back(from.normal[k]);
        next_.first.push_back(static_cast<int>(next_.points.size()));
        next_.count.push_back(from.count[k]);
        for (int j = 0; j < from.count[k]; ++j)
            next_.points.push_back(from.points[from.first[k] + j]);
    };
    for (int w = 0; w < static_cast<int>(found_.size()); ++w) {
        stats_.pairs += static_cast<int>(pairs_[w].size());
        for (int k = 0; k < found_[w].size(); ++k) append(found_[w], k);
    }
    narrow_count_ = next_.size();
    for (int k = 0; k < old.size(); ++k)
        if (!awake_[pair_first(old.pair[k])] && !awake_[pair_second(old.pair[k])]) append(old, k);
}

} // namespace tumble::physics
