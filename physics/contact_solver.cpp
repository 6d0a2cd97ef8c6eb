#include "physics/contact_solver.h"

#include "physics/contact_kernels.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tumble::physics {

Softness make_softness(double hertz, double zeta, double h) {
    if (hertz <= 0.0) return {};
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * zeta + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

namespace {

// 1/k along n and the tangent masses of point p at its current anchors.
void point_masses(const SolverManifold& c, SolverPoint& p, const BodyView& A, const BodyView& B) {
    p.normal_mass = 1.0 / (linear_normal_row(A, B) ? A.inv_mass + B.inv_mass
                                                   : effective_mass(A, B, p.ra, p.rb, c.normal));
    const Vec3 a1 = p.ra.cross(c.t1), a2 = p.ra.cross(c.t2);
    const Vec3 b1 = p.rb.cross(c.t1), b2 = p.rb.cross(c.t2);
    const Vec3 ia1 = inv_inertia_times(A, a1), ib1 = inv_inertia_times(B, b1);
    const double m = A.inv_mass + B.inv_mass;
    const double k11 = m + a1.dot(ia1) + b1.dot(ib1);
    const double k22 = m + a2.dot(inv_inertia_times(A, a2)) + b2.dot(inv_inertia_times(B, b2));
    const double k12 = a2.dot(ia1) + b2.dot(ib1);
    // K^-1 and 1 / (largest eigenvalue of K), K = [[k11, k12], [k12, k22]] (see coulomb()).
    const double det = k11 * k22 - k12 * k12;
    const double inv_det = det > 0.0 ? 1.0 / det : 0.0;
    const double mean = 0.5 * (k11 + k22), half = 0.5 * (k11 - k22);
    p.tangent_mass = {k22 * inv_det, -k12 * inv_det, k11 * inv_det,
                      1.0 / (mean + std::sqrt(half * half + k12 * k12))};
}

} // namespace

void prepare_manifold(SolverManifold& c, SolverPoint* points, PointAux* aux,
                      const SolverBodies& bodies, const State& s) {
    const BodyView A = body_view(bodies, c.a, c.move_a);
    const BodyView B = body_view(bodies, c.b, c.move_b);
    c.inv_mass_a = A.inv_mass, c.inv_i_a = A.inv_i, c.inertia_a = A.inv_inertia;
    c.inv_mass_b = B.inv_mass, c.inv_i_b = B.inv_i, c.inertia_b = B.inv_inertia;
    c.rotates_a = A.rotates, c.rotates_b = B.rotates;
    const Vec3& n = c.normal;
    // Tangents: a fixed perpendicular of n (Box3D's choice of axis), and n x t1.
    c.t1 = std::abs(n.x()) >= 0.57735 ? Vec3(n.y(), -n.x(), 0.0).normalized()
                                      : Vec3(0.0, n.z(), -n.y()).normalized();
    c.t2 = n.cross(c.t1);
    for (int k = 0; k < c.count; ++k) {
        SolverPoint& p = points[k];
        PointAux& x = aux[k];
        // p.ra/p.rb hold the world contact point on entry (see contact_prepare.cpp).
        const Vec3 point = p.ra;
        p.ra = point - s.x[c.a];
        p.rb = point - s.x[c.b];
        x.core_a = p.ra - bodies.rounding[c.a] * n; // A's core lies behind its surface (n: A to B)
        x.core_b = p.rb + bodies.rounding[c.b] * n;
        p.base_separation = x.separation0 - n.dot(p.rb - p.ra);
        point_masses(c, p, A, B);
        x.impact_normal = x.impact_vn = 0.0;
        x.impact_friction[0] = x.impact_friction[1] = 0.0;
    }
}

// The core point turns with the body and the surface point stays the radius away along the normal:
// a capsule rolling about its own axis keeps its contact at the bottom, where turning the surface
// point itself lifted it off the table (2.6 mm for 0.42 rad, r = 3 cm) while the capsule's other
// side sank 5 mm into it.
//
// A body that turns 0.4 rad in a step (a capsule lying on the table spun at 100 rad/s about the
// vertical, h = 1/240 s) carries its contact points around with it. With the anchors and masses of
// the step's start, its impulses went where the contact had been, and through the inertia the
// body now has about that old lever arm: for the capsule, its small moment about its own axis. It
// was kicked off its spin axis and gained energy without bound (1.5 E0 in one 1/120 s step with
// friction, +1e14 J at 48 substeps without).
void follow_manifold(const SolverManifold& c, SolverPoint* points, const PointAux* aux,
                     const SolverBodies& bodies) {
    const BodyView A = body_a(c), B = body_b(c);
    if (!A.rotates && !B.rotates) return;
    for (int k = 0; k < c.count; ++k) {
        SolverPoint& p = points[k];
        if (A.rotates) p.ra = bodies.turn[c.a] * aux[k].core_a + bodies.rounding[c.a] * c.normal;
        if (B.rotates) p.rb = bodies.turn[c.b] * aux[k].core_b - bodies.rounding[c.b] * c.normal;
        point_masses(c, p, A, B);
    }
}

void warm_start(const SolverManifold& c, const SolverPoint* points, SolverBody* sb) {
    const BodyView A = body_a(c), B = body_b(c);
    Velocity va = load(sb, c.a), vb = load(sb, c.b);
    for (int k = 0; k < c.count; ++k) {
        const SolverPoint& p = points[k];
        if (no_impulse(p.normal_impulse, p.friction_impulse)) continue; // nothing to warm with
        const Vec3 impulse = p.normal_impulse * c.normal + p.friction_impulse[0] * c.t1 +
                             p.friction_impulse[1] * c.t2;
        apply(A, va, p.ra, -impulse);
        apply(B, vb, p.rb, impulse);
    }
    store(sb, c.a, c.move_a, va);
    store(sb, c.b, c.move_b, vb);
}

void solve_manifold(const SolverManifold& c, SolverPoint* points, const SolverContext& ctx,
                    bool use_bias, SolverBody* sb) {
    const BodyView A = body_a(c), B = body_b(c);
    const Softness& soft = c.move_a && c.move_b ? ctx.soft : ctx.soft_static;
    Velocity va = load(sb, c.a), vb = load(sb, c.b);
    const Vec3& n = c.normal;
    // Motion of each centre since the start of the step (zero for a body that does not move); the
    // anchors have turned with the bodies (follow_manifold), so the separation now is
    // s = base + n.(dB + rB - dA - rA).
    const Vec3& da = sb[c.a].delta;
    const Vec3& db = sb[c.b].delta;

    // Non-penetration. Between spheres (or a sphere and a static body) the row neither reads nor
    // changes a spin (linear_normal_row): exact, where the general form adds rounding-level
    // angular terms.
    const bool linear = linear_normal_row(A, B);
    for (int k = 0; k < c.count; ++k) {
        SolverPoint& p = points[k];
        const double sep = p.base_separation + n.dot(db + p.rb - da - p.ra);
        double bias = 0.0, mass_scale = 1.0, impulse_scale = 0.0;
        if (sep > 0.0) {
            // Speculative: let the gap close exactly by the end of the substep, no faster. Only
            // in the solve: relaxing at the end of a substep would brake the approach already
            // (Box2D does), and the impact at the next step would see the braked speed.
            if (!use_bias) continue;
            bias = sep * ctx.inv_h;
        } else if (use_bias) {
            bias = std::max(soft.bias_rate * sep, -ctx.max_push_speed);
            mass_scale = soft.mass_scale;
            impulse_scale = soft.impulse_scale;
        }
        const double vn =
            linear ? n.dot(vb.v - va.v) : n.dot(relative_velocity(va, vb, p.ra, p.rb));
        double delta = -p.normal_mass * mass_scale * (vn + bias) - impulse_scale * p.normal_impulse;
        const double next = std::max(p.normal_impulse + delta, 0.0);
        delta = next - p.normal_impulse;
        if (delta == 0.0) continue; // no change: most often a speculative point held at zero
        p.normal_impulse = next;
        if (linear) {
            if (A.movable) va.v -= (A.inv_mass * delta) * n;
            if (B.movable) vb.v += (B.inv_mass * delta) * n;
            continue;
        }
        apply(A, va, p.ra, -delta * n);
        apply(B, vb, p.rb, delta * n);
    }

    // Friction: both tangent directions at once, within the disc |lambda_t| <= mu lambda_n.
    for (int k = 0; k < c.count; ++k) {
        SolverPoint& p = points[k];
        friction_at_point(c, p, A, B, p.normal_impulse, p.friction_impulse, va, vb);
    }
    store(sb, c.a, c.move_a, va);
    store(sb, c.b, c.move_b, vb);
}

} // namespace tumble::physics
