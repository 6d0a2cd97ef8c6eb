// Contact stage, part 3: impacts, then the substeps of Box2D v3's soft step around the named
// integrator, then impulse storage. The reasoning is at the top of step.cpp.
#include "physics/contact_stage.h"

#include <algorithm>

namespace tumble::physics {
namespace {

constexpr int kImpactSweeps = 8; // a blow crosses at most this many contacts of a chain per step

} // namespace

void ContactStage::solve_and_integrate(const Model& m, State& s, IntegrateFn integrate,
                                       ThreadPool& pool) {
    const int substeps = substep_count(m.contact, h_);
    stats_.substeps = substeps;
    const double h = h_ / substeps;
    SolverContext ctx;
    const double hertz = m.contact.contact_hertz_fraction / h;
    const double zeta = m.contact.contact_damping_ratio;
    ctx.soft = make_softness(hertz, zeta, h);
    ctx.soft_static = make_softness(2.0 * hertz, zeta, h);
    ctx.h = h;
    ctx.inv_h = 1.0 / h;
    ctx.step_h = h_;
    ctx.max_push_speed = m.contact.max_push_speed;
    ctx.restitution_threshold = m.contact.restitution_threshold;

    Stopwatch clock;
    profile_.impacts = profile_.solve = profile_.integrate = 0.0;
    sleeping_.clear();
    for (int i : m.dynamic_bodies)
        if (!awake_[i]) sleeping_.push_back(i);
    sleep_x_.resize(sleeping_.size());
    sleep_q_.resize(sleeping_.size());

    // Free flight: nothing to solve, the integrator takes the whole step (results identical to
    // a scene without contacts).
    if (manifolds_.empty()) {
        for (std::size_t k = 0; k < sleeping_.size(); ++k)
            sleep_x_[k] = s.x[sleeping_[k]], sleep_q_[k] = s.q[sleeping_[k]];
        integrate_all(m, s, integrate, h_, pool);
        stats_.substeps = 1;
        for (std::size_t k = 0; k < sleeping_.size(); ++k) {
            const int i = sleeping_[k];
            s.x[i] = sleep_x_[k], s.q[i] = sleep_q_[k];
            s.v[i] = Vec3::Zero(), s.w[i] = Vec3::Zero();
        }
        stats_.impacts = 0;
        profile_.integrate = clock.lap();
        return;
    }

    // Impacts first, on the velocities at the start of the step.
    impact_flags_.assign(pool.size(), 0);
    stats_.impacts = 0;
    for (int sweep = 0; sweep < kImpactSweeps; ++sweep) {
        std::fill(impact_flags_.begin(), impact_flags_.end(), 0);
        for_each_colour(pool, [&](int begin, int end, int worker) {
            for (int c = begin; c < end; ++c)
                if (resolve_impacts(manifolds_[c], &points_[manifolds_[c].first], bodies_, ctx, s))
                    impact_flags_[worker] = 1;
        });
        if (std::find(impact_flags_.begin(), impact_flags_.end(), 1) == impact_flags_.end()) break;
        ++stats_.impacts;
    }
    // Impacts that happened in isolation move to the moment of contact (contact_impacts.cpp).
    shifted_.clear();
    if (stats_.impacts > 0) {
        impact_count_.assign(m.body_count(), 0);
        for (const SolverManifold& c : manifolds_) {
            bool hit = false;
            for (int k = 0; k < c.count; ++k) hit |= points_[c.first + k].impact_normal != 0.0;
            if (!hit) continue;
            impact_count_[c.a] += c.move_a;
            impact_count_[c.b] += c.move_b;
        }
        shift_.resize(m.body_count());
        for (const SolverManifold& c : manifolds_) {
            if ((c.move_a && impact_count_[c.a] != 1) || (c.move_b && impact_count_[c.b] != 1))
                continue;
            double ds = 0.0;
            if (!impact_in_step(c, &points_[c.first], bodies_, ctx, s, ds)) continue;
            const double ma = c.move_a ? m.inv_mass[c.a] : 0.0;
            const double mb = c.move_b ? m.inv_mass[c.b] : 0.0;
            if (c.move_a) shift_[c.a] = -ds * ma / (ma + mb) * c.normal, shifted_.push_back(c.a);
            if (c.move_b) shift_[c.b] = ds * mb / (ma + mb) * c.normal, shifted_.push_back(c.b);
        }
    }
    profile_.impacts = clock.lap();

    const int nc = static_cast<int>(constrained_.size());
    solved_v_.resize(nc);
    before_x_.resize(nc);
    // Motion of each constrained body since the start of the step, and its world inverse inertia
    // I_w^-1 = R I_body^-1 R^T at the current orientation. A top spinning at 75 rad/s turns 0.3 rad
    // in a step; impulses applied through the inertia of the step's start changed w by the wrong
    // amount, and a spinning top on a plane gained energy (+0.5% in 2 s with 8 substeps).
    auto track = [&] {
        pool.for_ranges(nc, 512, [&](int begin, int end, int) {
            for (int k = begin; k < end; ++k) {
                const int i = constrained_[k];
                bodies_.delta[i] = s.x[i] - bodies_.x0[i];
                if (bodies_.rotates[i])
                    bodies_.turn[i] = (s.q[i] * bodies_.q0[i].conjugate()).toRotationMatrix();
                if (!bodies_.isotropic[i]) {
                    const Mat3 r = s.q[i].toRotationMatrix();
                    bodies_.inv_inertia[i] = r * m.inv_inertia[i].asDiagonal() * r.transpose();
                }
            }
        });
    };
    for (int sub = 0; sub < substeps; ++sub) {
        // 1. Predict: the solver sees the velocities the loads would give at the substep's end.
        track();
        for (int i : constrained_) {
            s.v[i] += h * bodies_.accel[i];
            s.w[i] += h * bodies_.ang_accel[i];
        }
        // 2. Warm start and solve with the soft push-out.
        for_each_colour(pool, [&](int begin, int end, int) {
            for (int c = begin; c < end; ++c)
                warm_start(manifolds_[c], &points_[manifolds_[c].first], bodies_, s);
        });
        for_each_colour(pool, [&](int begin, int end, int) {
            for (int c = begin; c < end; ++c)
                solve_manifold(manifolds_[c], &points_[manifolds_[c].first], bodies_, ctx, true, s);
        });
        // 3. Free flight by the named integrator. Bodies in contact hand it the velocity before
        // the loads (it adds them back) and then move by h times the solved velocity, the
        // symplectic position update the constraints assumed; see step.cpp for why.
        for (int k = 0; k < nc; ++k) {
            const int i = constrained_[k];
            solved_v_[k] = s.v[i];
            before_x_[k] = s.x[i];
            s.v[i] -= h * bodies_.accel[i];
            s.w[i] -= h * bodies_.ang_accel[i];
        }
        profile_.solve += clock.lap();
        for (std::size_t k = 0; k < sleeping_.size(); ++k)
            sleep_x_[k] = s.x[sleeping_[k]], sleep_q_[k] = s.q[sleeping_[k]];
        integrate_all(m, s, integrate, h, pool);
        for (std::size_t k = 0; k < sleeping_.size(); ++k) {
            const int i = sleeping_[k];
            s.x[i] = sleep_x_[k], s.q[i] = sleep_q_[k];
            s.v[i] = Vec3::Zero(), s.w[i] = Vec3::Zero();
        }
        for (int k = 0; k < nc; ++k) {
            const int i = constrained_[k];
            s.x[i] = before_x_[k] + h * solved_v_[k];
            s.v[i] = solved_v_[k];
        }
        profile_.integrate += clock.lap();
        // 4. Relax: solve again without the push-out bias, so that it moved positions only.
        track();
        for_each_colour(pool, [&](int begin, int end, int) {
            for (int c = begin; c < end; ++c)
                solve_manifold(manifolds_[c], &points_[manifolds_[c].first], bodies_, ctx, false,
                               s);
        });
        profile_.solve += clock.lap();
    }
    for (int i : shifted_) s.x[i] += shift_[i];
}

// The integrator over every dynamic body, in fixed contiguous ranges per worker: a body's update
// touches only its own state, so the bits are those of one thread. An integrator that fails
// (midpoint's Newton solve throws DivergenceError) may do so on any worker; the error of the
// lowest range is rethrown, which is the body a single thread would have stopped at.
void ContactStage::integrate_all(const Model& m, State& s, IntegrateFn integrate, double h,
                                 ThreadPool& pool) {
    const std::span<const int> all(m.dynamic_bodies);
    integrate_errors_.assign(pool.size(), nullptr);
    pool.for_ranges(static_cast<int>(all.size()), 256, [&](int begin, int end, int worker) {
        try {
            integrate(m, s, h, all.subspan(begin, end - begin));
        } catch (...) {
            integrate_errors_[worker] = std::current_exception();
        }
    });
    for (const std::exception_ptr& e : integrate_errors_)
        if (e) std::rethrow_exception(e);
}

void ContactStage::store_impulses() {
    for (const SolverManifold& c : manifolds_) {
        const SolverPoint* pts = &points_[c.first];
        for (int j = 0; j < c.count; ++j) {
            CachedPoint& q = next_.points[next_.first[c.cache] + j];
            q.normal_impulse = pts[j].normal_impulse;
            q.friction_impulse =
                pts[j].friction_impulse[0] * c.t1 + pts[j].friction_impulse[1] * c.t2;
        }
    }
}

} // namespace tumble::physics
