#pragma once
// Small inline helpers shared by the contact solver's kernels: a body's mass properties as the
// solver sees them (zero for a body that does not move) and velocity load/apply/store.
#include "physics/contact_solver.h"

#include <cmath>

namespace tumble::physics {

// A body as the solver sees it. Isotropic bodies (spheres, cubes) have I_w^-1 = (1/I) 1 in any
// orientation: a scalar, no matrix product (most contacts of a sphere pile).
struct BodyView {
    double inv_mass;
    double inv_i;            // isotropic: the scalar 1/I
    const Mat3* inv_inertia; // otherwise: I_w^-1 (null for isotropic)
    bool movable, rotates;
};

inline BodyView body_view(const SolverBodies& b, int i, bool movable) {
    if (!movable) return {0.0, 0.0, nullptr, false, false};
    const bool iso = b.isotropic[i] != 0;
    return {b.inv_mass[i], b.inv_i[i], iso ? nullptr : &b.inv_inertia[i], true, b.rotates[i] != 0};
}

// The same views as kept in the constraint (prepare_manifold), read without the body arrays.
inline BodyView body_a(const SolverManifold& c) {
    return {c.inv_mass_a, c.inv_i_a, c.inertia_a, c.move_a != 0, c.rotates_a != 0};
}
inline BodyView body_b(const SolverManifold& c) {
    return {c.inv_mass_b, c.inv_i_b, c.inertia_b, c.move_b != 0, c.rotates_b != 0};
}

// A sphere's contact point lies on the normal through its centre (collide_round.cpp,
// collide_hull_round.cpp: the point is the centre moved along n), so r = (n.r) n and, for the
// normal, n.(w x r) = w.(r x n) = 0 and r x (lambda n) = 0. With both bodies spheres, or a sphere
// and a body that does not move (no turning anchors: BodyView::rotates is false for exactly those),
// the normal row is linear in the velocities: vn = n.(vB - vA), k = 1/mA + 1/mB.
inline bool linear_normal_row(const BodyView& a, const BodyView& b) {
    return !a.rotates && !b.rotates;
}

// I_w^-1 v
inline Vec3 inv_inertia_times(const BodyView& b, const Vec3& v) {
    return b.inv_inertia ? Vec3(*b.inv_inertia * v) : Vec3(b.inv_i * v);
}

struct Velocity {
    Vec3 v, w;
};

// Static and sleeping bodies have v = w = 0 in the state, so reading them is always right.
inline Velocity load(const State& s, int i) {
    return {s.v[i], s.w[i]};
}

inline void store(State& s, int i, bool movable, const Velocity& vel) {
    if (!movable) return;
    s.v[i] = vel.v;
    s.w[i] = vel.w;
}

// The same on the solver's packed records (the substeps' sweeps).
inline Velocity load(const SolverBody* sb, int i) {
    return {sb[i].v, sb[i].w};
}

inline void store(SolverBody* sb, int i, bool movable, const Velocity& vel) {
    if (!movable) return;
    sb[i].v = vel.v;
    sb[i].w = vel.w;
}

inline Vec3 relative_velocity(const Velocity& a, const Velocity& b, const Vec3& ra,
                              const Vec3& rb) {
    return b.v + b.w.cross(rb) - a.v - a.w.cross(ra);
}

// Impulse p at anchor r: v += p / m, w += I^-1 (r x p). No-op for a body that does not move.
inline void apply(const BodyView& body, Velocity& vel, const Vec3& r, const Vec3& p) {
    if (!body.movable) return;
    vel.v += body.inv_mass * p;
    vel.w += inv_inertia_times(body, r.cross(p));
}

// k = mA^-1 + mB^-1 + (rA x d) . IA^-1 (rA x d) + (rB x d) . IB^-1 (rB x d)
inline double effective_mass(const BodyView& a, const BodyView& b, const Vec3& ra, const Vec3& rb,
                             const Vec3& d) {
    const Vec3 rad = ra.cross(d), rbd = rb.cross(d);
    return a.inv_mass + b.inv_mass + rad.dot(inv_inertia_times(a, rad)) +
           rbd.dot(inv_inertia_times(b, rbd));
}

// A point that carries no impulse yet: no push, no friction. About half the points of a sphere
// rain are such speculative points (close, not touching); warming or rubbing them is a no-op.
inline bool no_impulse(double normal_impulse, const double lambda[2]) {
    return normal_impulse == 0.0 && lambda[0] == 0.0 && lambda[1] == 0.0;
}

// Coulomb friction at one point, for the accumulated tangent impulse (l1, l2) and the tangential
// slip velocity (v1, v2). Sticking: the impulse that stops the slip exactly, l - K^-1 v with K the
// 2x2 effective-mass matrix of the two tangents, if it lies in the disc |l| <= limit. Otherwise
// sliding: l - m v with the scalar m = 1 / (largest eigenvalue of K), put back on the disc. The
// usual "scale the sticking impulse back onto the disc" settles along K^-1 v instead of -v when K
// couples the tangents (any point off the line through the centre of mass, a box corner): a box
// sliding down a 30 degree ramp then felt 10% less friction than mu N. With a scalar mass the
// fixed point of sliding is exactly -limit v / |v| (maximal dissipation). A scalar mass also for
// sticking would converge slowly where K is far from round: a pyramid of boxes kept jiggling.
inline void coulomb(const TangentMass& mass, double v1, double v2, double limit, double& l1,
                    double& l2) {
    const double s1 = l1 - (mass.k11 * v1 + mass.k12 * v2);
    const double s2 = l2 - (mass.k12 * v1 + mass.k22 * v2);
    if (s1 * s1 + s2 * s2 <= limit * limit) {
        l1 = s1, l2 = s2;
        return;
    }
    l1 -= mass.scalar * v1;
    l2 -= mass.scalar * v2;
    const double len2 = l1 * l1 + l2 * l2;
    if (len2 > limit * limit) {
        const double scale = limit / std::sqrt(len2);
        l1 *= scale;
        l2 *= scale;
    }
}

// Friction at one point of manifold c: the accumulated tangent impulse `lambda` (along t1, t2)
// takes one coulomb() update for the slip at the point, within mu times `normal_impulse`, and the
// change is applied to both bodies. Used by the solver (the step's impulses) and by the impacts
// (each impact's own).
inline void friction_at_point(const SolverManifold& c, const SolverPoint& p, const BodyView& A,
                              const BodyView& B, double normal_impulse, double lambda[2],
                              Velocity& va, Velocity& vb) {
    // No push and no friction yet: the disc has radius 0 and lambda is at its centre already.
    if (no_impulse(normal_impulse, lambda)) return;
    const Vec3 vr = relative_velocity(va, vb, p.ra, p.rb);
    double l1 = lambda[0], l2 = lambda[1];
    coulomb(p.tangent_mass, c.t1.dot(vr), c.t2.dot(vr), c.friction * normal_impulse, l1, l2);
    const Vec3 impulse = (l1 - lambda[0]) * c.t1 + (l2 - lambda[1]) * c.t2;
    lambda[0] = l1;
    lambda[1] = l2;
    apply(A, va, p.ra, -impulse);
    apply(B, vb, p.rb, impulse);
}

} // namespace tumble::physics
