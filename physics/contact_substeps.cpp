// Contact stage, substeps: Box2D v3's soft step around the named integrator, n times per step
// with h' = h / n. Each substep is predict, solve, integrate, relax; the reasoning is at the top of
// step.cpp. Without constraints the integrator takes the whole step instead (free_flight).
#include "physics/contact_stage.h"

namespace tumble::physics {

void ContactStage::substeps(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool) {
    Stopwatch clock;
    plan_effort(m, s); // contact_effort.cpp
    profile_.prepare += clock.lap();
    stats_.substeps = stats_.effort.substeps_max;
    stats_.sweeps = stats_.effort.sweeps_max;
    for (int k = 0; k < group_count_; ++k) {
        const SubstepGroup& g = groups_[k];
        solved_v_.resize(g.bodies.size());
        before_x_.resize(g.bodies.size());
        predicted_v_.resize(g.bodies.size());
        predicted_w_.resize(g.bodies.size());
        for (int sub = 0; sub < g.substeps; ++sub) {
            predict(m, s, pool, g);
            solve(pool, g);
            profile_.solve += clock.lap();
            integrate_substep(m, s, integrate, pool, g);
            profile_.integrate += clock.lap();
            relax(m, s, pool, g);
            profile_.solve += clock.lap();
        }
    }
    if (!fixed_) {
        // Bodies in no constraint cannot touch anything within the step (their speculative
        // margins say so): the integrator takes them over the whole step h.
        integrate_all(m, s, integrate, h_, free_, pool);
        scale_warm_start(false); // the State holds impulses per step (contact_effort.cpp)
        profile_.integrate += clock.lap();
    }
}

// Nothing to solve: the integrator takes the whole step (results identical to a scene without
// contacts).
void ContactStage::free_flight(const Model& m, State& s, IntegrateFn integrate, ThreadPool& pool) {
    Stopwatch clock;
    integrate_awake(m, s, integrate, h_, pool);
    stats_.substeps = 1;
    stats_.sweeps = 0;
    stats_.effort = {};
    stats_.impacts = 0;
    profile_.integrate = clock.lap();
}

// a. Predict: the solver sees the velocities the loads would give at the substep's end. From here
// to the integrator the velocities of the group's bodies live in solver_bodies_.
void ContactStage::predict(const Model& m, const State& s, ThreadPool& pool,
                           const SubstepGroup& g) {
    track_motion(m, s, pool, g);
    follow_bodies(pool, g);
    pool.for_ranges(static_cast<int>(g.bodies.size()), 512, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int i = g.bodies[k];
            SolverBody& b = solver_bodies_[i];
            b.v = s.v[i] + g.ctx.h * bodies_.accel[i];
            b.w = s.w[i] + g.ctx.h * bodies_.ang_accel[i];
            predicted_v_[k] = b.v;
            predicted_w_[k] = b.w;
        }
    });
}

// b. Warm start, then the solve sweeps with the soft push-out (contact_sweeps.cpp). One sweep
// carries a change of load one contact down a stack per substep; with one sweep of fixed effort a
// stack of 5 boxes rocked, and a cube 1000 times heavier than the one below it slid off it
// (docs/contacts.md).
void ContactStage::solve(ThreadPool& pool, const SubstepGroup& g) {
    for_each_listed(pool, g.slots, g.starts, [&](int c, int) {
        warm_start(manifolds_[c], &points_[manifolds_[c].first], solver_bodies_.data());
    });
    sweeps(pool, g, true);
}

// c. Free flight by the named integrator. Bodies in contact hand it the velocity before the loads
// (it adds them back) and then move by h' times the solved velocity, the symplectic position
// update the constraints assumed; see step.cpp for why. Fixed effort integrates every awake body
// at each substep, as before effort on demand; on demand only the group's bodies, and a body the
// solve did not push (warm start and sweeps left its v and w as predicted: its speculative
// contacts never closed) keeps the integrator's free flight. The symplectic update puts such a
// body 1/2 a h'^2 below its parabola per substep: a low bounce, flying wholly inside its
// speculative margin, landed about a step early per bounce at one substep (lesson 10's ball:
// 3 steps early by the tenth bounce). The gap it ends with is at least the one the solve assumed
// when its load points towards the contact, and at most 1/2 h'^2 a.n smaller when it points away.
void ContactStage::integrate_substep(const Model& m, State& s, IntegrateFn integrate,
                                     ThreadPool& pool, const SubstepGroup& g) {
    const double h = g.ctx.h;
    const int nb = static_cast<int>(g.bodies.size());
    pushed_.resize(nb);
    // Each loop touches only its own body's state: fixed ranges per worker, the bits of one thread.
    pool.for_ranges(nb, 512, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int i = g.bodies[k];
            const SolverBody& b = solver_bodies_[i];
            pushed_[k] = b.v != predicted_v_[k] || b.w != predicted_w_[k];
            solved_v_[k] = b.v;
            before_x_[k] = s.x[i];
            s.v[i] = b.v - h * bodies_.accel[i];
            s.w[i] = b.w - h * bodies_.ang_accel[i];
        }
    });
    if (fixed_)
        integrate_awake(m, s, integrate, h, pool);
    else
        integrate_all(m, s, integrate, h, g.bodies, pool);
    pool.for_ranges(nb, 512, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int i = g.bodies[k];
            if (!fixed_ && !pushed_[k]) continue; // flew freely: the integrator's motion stands
            s.x[i] = before_x_[k] + h * solved_v_[k];
            s.v[i] = solved_v_[k];
        }
    });
}

// d. Relax: solve again without the push-out bias, so that it moved positions only. Fixed effort
// makes two sweeps: one left a pair of boxes pushed apart face on face with 2.4% of the push as
// kinetic energy.
void ContactStage::relax(const Model& m, State& s, ThreadPool& pool, const SubstepGroup& g) {
    track_motion(m, s, pool, g);
    follow_bodies(pool, g);
    load_velocities(s, pool, g);
    sweeps(pool, g, false);
    store_velocities(s, pool, g);
}

// The group's velocities into the solver's records before a relax, and back after it.
void ContactStage::load_velocities(const State& s, ThreadPool& pool, const SubstepGroup& g) {
    pool.for_ranges(static_cast<int>(g.bodies.size()), 512, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int i = g.bodies[k];
            solver_bodies_[i].v = s.v[i];
            solver_bodies_[i].w = s.w[i];
        }
    });
}

void ContactStage::store_velocities(State& s, ThreadPool& pool, const SubstepGroup& g) {
    pool.for_ranges(static_cast<int>(g.bodies.size()), 512, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int i = g.bodies[k];
            s.v[i] = solver_bodies_[i].v;
            s.w[i] = solver_bodies_[i].w;
        }
    });
}

// Motion of each constrained body since the start of the step, and its world inverse inertia
// I_w^-1 = R I_body^-1 R^T at the current orientation. A top spinning at 75 rad/s turns 0.3 rad in
// a step; impulses applied through the inertia of the step's start changed w by the wrong amount,
// and a spinning top on a plane gained energy (+0.5% in 2 s with 8 substeps).
void ContactStage::track_motion(const Model& m, const State& s, ThreadPool& pool,
                                const SubstepGroup& g) {
    pool.for_ranges(static_cast<int>(g.bodies.size()), 512, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int i = g.bodies[k];
            solver_bodies_[i].delta = s.x[i] - bodies_.x0[i];
            if (bodies_.rotates[i])
                bodies_.turn[i] = (s.q[i] * bodies_.q0[i].conjugate()).toRotationMatrix();
            if (!bodies_.isotropic[i]) {
                const Mat3 r = s.q[i].toRotationMatrix();
                bodies_.inv_inertia[i] = r * m.inv_inertia[i].asDiagonal() * r.transpose();
            }
        }
    });
}

// Anchors and effective masses at the bodies' current orientation (follow_manifold,
// contact_solver.cpp), for the manifolds with a body that turns.
void ContactStage::follow_bodies(ThreadPool& pool, const SubstepGroup& g) {
    if (!g.turns) return; // follow_manifold would leave every manifold as it is
    for_each_listed(pool, g.slots, g.starts, [&](int c, int) {
        follow_manifold(manifolds_[c], &points_[manifolds_[c].first], &aux_[manifolds_[c].first],
                        bodies_);
    });
}

// The integrator over every dynamic body, then the sleeping ones put back: the integrator's
// interface steps every dynamic body, and a sleeping body keeps its pose with v = w = 0.
void ContactStage::integrate_awake(const Model& m, State& s, IntegrateFn integrate, double h,
                                   ThreadPool& pool) {
    for (std::size_t k = 0; k < sleeping_.size(); ++k)
        sleep_x_[k] = s.x[sleeping_[k]], sleep_q_[k] = s.q[sleeping_[k]];
    integrate_all(m, s, integrate, h, m.dynamic_bodies, pool);
    for (std::size_t k = 0; k < sleeping_.size(); ++k) {
        const int i = sleeping_[k];
        s.x[i] = sleep_x_[k], s.q[i] = sleep_q_[k];
        s.v[i] = Vec3::Zero(), s.w[i] = Vec3::Zero();
    }
}

// The integrator over the listed bodies, in fixed contiguous ranges per worker: a body's update
// touches only its own state, so the bits are those of one thread. An integrator that fails
// (midpoint's Newton solve throws DivergenceError) may do so on any worker; the error of the
// lowest range is rethrown, which is the body a single thread would have stopped at.
void ContactStage::integrate_all(const Model& m, State& s, IntegrateFn integrate, double h,
                                 std::span<const int> all, ThreadPool& pool) {
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

} // namespace tumble::physics
