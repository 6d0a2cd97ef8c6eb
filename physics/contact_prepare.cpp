// Contact stage, prepare: what the impacts and the substeps solve with. Mass properties and loads
// of the awake bodies at the start of the step; the constraints (one per manifold with a body that
// moves) in graph-colour order, so that no colour holds two constraints on one moving body;
// their anchors, effective masses and tangents (prepare_manifold, contact_solver.cpp); the
// softness of the substep; and the sleeping bodies, whose poses the integrator must not change.
#include "physics/contact_stage.h"

#include "physics/forces.h"

#include <algorithm>

namespace tumble::physics {

void ContactStage::prepare(const Model& m, const State& s, ThreadPool& pool) {
    Stopwatch clock;
    prepare_bodies(m, s, pool);
    colour_constraints(m);
    assign_slots();
    prepare_constraints(m, s, pool);
    prepare_context(m);
    sleeping_.clear();
    for (int i : m.dynamic_bodies)
        if (!awake_[i]) sleeping_.push_back(i);
    sleep_x_.resize(sleeping_.size());
    sleep_q_.resize(sleeping_.size());
    profile_.prepare = clock.lap();
}

// Mass properties and loads of the awake bodies, at the start of the step.
void ContactStage::prepare_bodies(const Model& m, const State& s, ThreadPool& pool) {
    const int n = m.body_count();
    bodies_.inv_inertia.resize(n);
    bodies_.inv_i.resize(n);
    bodies_.isotropic.resize(n);
    bodies_.inv_mass.resize(n);
    bodies_.x0.resize(n);
    bodies_.q0.resize(n);
    bodies_.turn.resize(n);
    bodies_.rotates.resize(n);
    bodies_.rounding.resize(n);
    bodies_.accel.resize(n);
    bodies_.ang_accel.resize(n);
    solver_bodies_.resize(n);
    pool.for_ranges(n, 256, [&](int begin, int end, int) {
        for (int i = begin; i < end; ++i) {
            // Static and sleeping bodies: v = w = 0 in the State, and they do not move.
            solver_bodies_[i] = {s.v[i], s.w[i], Vec3::Zero()};
            bodies_.rounding[i] = m.shape[i].kind == ShapeKind::Capsule ? m.shape[i].radius : 0.0;
            if (!awake_[i]) continue;
            bodies_.isotropic[i] = m.isotropic[i];
            bodies_.inv_i[i] = m.inv_inertia[i].x();
            if (!m.isotropic[i]) {
                const Mat3 r = s.q[i].toRotationMatrix();
                bodies_.inv_inertia[i] = r * m.inv_inertia[i].asDiagonal() * r.transpose();
            }
            bodies_.inv_mass[i] = m.inv_mass[i];
            bodies_.x0[i] = s.x[i];
            bodies_.q0[i] = s.q[i];
            bodies_.turn[i] = Mat3::Identity();
            bodies_.rotates[i] = m.shape[i].kind != ShapeKind::Sphere;
            bodies_.accel[i] = m.inv_mass[i] * net_force(m, i);
            bodies_.ang_accel[i] = m.isotropic[i] ? Vec3(bodies_.inv_i[i] * net_torque(m, i))
                                                  : Vec3(bodies_.inv_inertia[i] * net_torque(m, i));
        }
    });
}

// Greedy colouring in cache order: each manifold with a moving body takes the lowest colour whose
// bodies exclude both of its moving bodies (kOverflow when none of the kColours does).
void ContactStage::colour_constraints(const Model& m) {
    const int n = m.body_count();
    const int count = next_.size();
    const int words = (n + 63) / 64;
    colour_bits_.assign(static_cast<std::size_t>(kColours) * words, 0);
    colour_of_.assign(count, -1);
    colour_start_.assign(kColours + 2, 0);
    in_constraint_.assign(n, 0);
    stats_.points = static_cast<int>(next_.points.size());
    stats_.max_overlap = 0.0;
    for (const CachedPoint& p : next_.points)
        stats_.max_overlap = std::max(stats_.max_overlap, -p.separation);
    for (int k = 0; k < count; ++k) {
        const int a = pair_first(next_.pair[k]), b = pair_second(next_.pair[k]);
        const bool ma = awake_[a], mb = awake_[b];
        if (!ma && !mb) continue;
        in_constraint_[a] |= ma;
        in_constraint_[b] |= mb;
        int c = 0;
        for (; c < kColours; ++c) {
            std::uint64_t* bits = &colour_bits_[static_cast<std::size_t>(c) * words];
            const bool busy =
                (ma && (bits[a >> 6] >> (a & 63) & 1)) || (mb && (bits[b >> 6] >> (b & 63) & 1));
            if (busy) continue;
            if (ma) bits[a >> 6] |= std::uint64_t{1} << (a & 63);
            if (mb) bits[b >> 6] |= std::uint64_t{1} << (b & 63);
            break;
        }
        colour_of_[k] = c;
        ++colour_start_[c + 1];
    }
    for (int c = 0; c <= kColours; ++c) colour_start_[c + 1] += colour_start_[c];
    colour_count_ = 0;
    for (int c = 0; c <= kColours; ++c)
        if (colour_start_[c + 1] > colour_start_[c]) colour_count_ = c + 1;
    stats_.colours = colour_count_;
}

// Slots: manifold k of colour c goes to the next free slot of c, which notes k (its cache);
// points follow in the same order.
void ContactStage::assign_slots() {
    const int count = next_.size();
    const int constraints = colour_start_[kColours + 1];
    stats_.constraints = constraints;
    manifolds_.resize(constraints);
    point_start_.assign(constraints + 1, 0);
    cursor_.assign(colour_start_.begin(), colour_start_.end());
    for (int k = 0; k < count; ++k) {
        if (colour_of_[k] < 0) continue;
        const int slot = cursor_[colour_of_[k]]++;
        manifolds_[slot].cache = k;
        point_start_[slot + 1] = next_.count[k];
    }
    for (int c = 0; c < constraints; ++c) point_start_[c + 1] += point_start_[c];
    points_.resize(point_start_[constraints]);
    aux_.resize(point_start_[constraints]);
}

// Each constraint from its manifold: bodies, materials, points with last step's impulses. In slot
// order, so that the constraints and their points are written in sequence and the cache's
// manifolds read out of order: the 8000-sphere rain's stage went from 7.8 and 8.1 to 7.0 and 6.9 ms
// per step (28,000 constraints; alternated, one thread).
void ContactStage::prepare_constraints(const Model& m, const State& s, ThreadPool& pool) {
    pool.for_ranges(static_cast<int>(manifolds_.size()), 256, [&](int begin, int end, int) {
        for (int slot = begin; slot < end; ++slot) {
            const int k = manifolds_[slot].cache;
            const int a = pair_first(next_.pair[k]), b = pair_second(next_.pair[k]);
            SolverManifold& c = manifolds_[slot];
            c.a = a, c.b = b;
            c.move_a = awake_[a], c.move_b = awake_[b];
            c.normal = next_.normal[k];
            c.friction = mix_friction(m.material[a], m.material[b]);
            c.restitution = mix_restitution(m.material[a], m.material[b]);
            c.first = point_start_[slot];
            c.count = next_.count[k];
            SolverPoint* pts = &points_[c.first];
            PointAux* aux = &aux_[c.first];
            for (int j = 0; j < c.count; ++j) {
                const CachedPoint& q = next_.points[next_.first[k] + j];
                pts[j].ra = q.point; // prepare_manifold() turns it into the anchors
                aux[j].separation0 = q.separation;
                pts[j].normal_impulse = q.normal_impulse;
            }
            prepare_manifold(c, pts, aux, bodies_, s);
            for (int j = 0; j < c.count; ++j) { // last step's friction on this step's tangents
                const Vec3& f = next_.points[next_.first[k] + j].friction_impulse;
                pts[j].friction_impulse[0] = f.dot(c.t1);
                pts[j].friction_impulse[1] = f.dot(c.t2);
            }
        }
    });
    constrained_.clear();
    for (int i = 0; i < m.body_count(); ++i)
        if (in_constraint_[i]) constrained_.push_back(i);
}

// The step's solver context, for the impacts (which look ahead over the whole step); each group
// of islands gets its substep's own (contact_effort.cpp).
void ContactStage::prepare_context(const Model& m) {
    ctx_ = solver_context(m, h_, fixed_effort(m.contact) ? substep_count(m.contact, h_) : 1);
}

} // namespace tumble::physics
