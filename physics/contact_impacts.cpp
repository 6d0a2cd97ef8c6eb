// Contact stage, impacts: restitution as sequential pairwise collisions at the start of the step,
// before the substeps (ContactStage::impacts), and the in-step correction applied after them
// (ContactStage::apply_impact_shifts). The kernels per manifold are declared in contact_solver.h.
//
// A point whose bodies approach at least as fast as the restitution threshold, and whose gap will
// close within this step if they keep flying freely, is an impact: the pair gets the normal impulse
// of a two-body collision with Newton's coefficient e (and Coulomb friction limited by mu times
// that impulse), as if nothing else touched them. Contacts are swept in colour order until no
// impact is left (at most 8 sweeps), so a blow travels along a chain one collision at a time:
// Newton's cradle sends one ball out for one ball in. Each pairwise collision conserves momentum
// exactly and, with e <= 1, cannot add energy. (Guendelman, Bridson, Fedkiw, "Nonconvex rigid
// bodies with stacking", 2003, separate collisions from resting contact in the same way; Box2D
// instead applies e after the solve, which makes every touching pair of a chain one inelastic
// lump.) The threshold is on the approach speed, as in Box2D (its contact solver compares the
// relative normal velocity with restitutionThreshold): an impact at least that fast bounces with e,
// however small the rebound; a slower one is left to the solver, whose speculative constraint
// brings the bodies exactly into contact by the end of the step. (Comparing the rebound e V
// instead took one bounce off a dropped ball for no reason a user could see.)
//
// Bouncing inside the step. The surfaces meet at some t_i in (0, h], not at the start. With s0
// the gap now, vn < 0 the normal velocity and a the relative normal acceleration of gravity and
// the applied loads, free flight keeps E = 1/2 vn^2 - a s constant, so the speed at contact is
//   V^2 = vn^2 - 2 a s0,   t_i = 2 s0 / (-vn + V)
// and the bounce leaves with u = e V. Applied now, at gap s0, the pair leaves with the speed that
// gives its normal motion the same energy:
//   vn'^2 = u^2 + 2 a s0,
// so a ball dropped on a floor reaches exactly e^2 times its previous apex, whatever the step.
// It would also turn round s0 short of the surface (up to |vn| h: a 50 m/s ball would stop 20 cm
// before a wall), so where one pair collides in isolation (neither body in another impact this
// step) the pair is then moved along the normal, in inverse proportion to the masses, by
//   ds = s_true - s_early,  s_true = u tau + 1/2 a tau^2 (tau = h - t_i),
//   s_early = s0 + (u - a t_i) h + 1/2 a h^2,
// and its normal velocity set to u - a t_i (so that the step ends with u + a tau), which puts it
// where and how fast the bounce at t_i would have: touching, then leaving. (For one impacting
// point; in a chain, or a face landing on several points at once, the corrections would interact,
// and the turn-round stays early by at most |vn| h with the energy still exact.)
#include "physics/contact_kernels.h"
#include "physics/contact_stage.h"

#include <algorithm>
#include <cmath>

namespace tumble::physics {
namespace {

constexpr double kArrival = 1e-4; // m
constexpr int kImpactSweeps = 8;  // a blow crosses at most this many contacts of a chain per step

double normal_acceleration(const SolverManifold& c, const SolverBodies& bodies) {
    const Vec3 acc_a = c.move_a ? bodies.accel[c.a] : Vec3(Vec3::Zero());
    const Vec3 acc_b = c.move_b ? bodies.accel[c.b] : Vec3(Vec3::Zero());
    return c.normal.dot(acc_b - acc_a);
}

} // namespace

bool resolve_impacts(const SolverManifold& c, const SolverPoint* points, PointAux* aux,
                     const SolverBodies& bodies, const SolverContext& ctx, State& s) {
    const BodyView A = body_a(c), B = body_b(c);
    // e = 0 never bounces: the solver's speculative contact stops the pair (as Box2D skips
    // restitution 0), so the impact pass costs nothing in scenes without bounce.
    if (c.restitution == 0.0) return false;
    const Vec3& n = c.normal;
    const double h = ctx.step_h, threshold = ctx.restitution_threshold;
    double an = 0.0; // the relative normal acceleration, once a point approaches fast enough
    Velocity va = load(s, c.a), vb = load(s, c.b);
    bool any = false;
    for (int k = 0; k < c.count; ++k) {
        const SolverPoint& p = points[k];
        PointAux& x = aux[k];
        const double vn = n.dot(relative_velocity(va, vb, p.ra, p.rb));
        if (vn >= -threshold) continue;
        if (!any) an = normal_acceleration(c, bodies);
        const double s0 = std::max(x.separation0, 0.0);
        // Closes within the step? The gap at its end under the symplectic update the solver uses
        // (s0 + vn h + a h^2, at most 1/2 a h^2 from free flight), with 0.1 mm to spare: a pair
        // arriving just at the end would otherwise reach the relax sweep, which stops it
        // inelastically (a cradle would move as one lump).
        if (s0 + vn * h + an * h * h > kArrival) continue;
        const double speed = std::sqrt(std::max(vn * vn - 2.0 * an * s0, 0.0)); // V
        const double out = c.restitution * speed;                               // u
        const double target = std::sqrt(std::max(out * out + 2.0 * an * s0, 0.0));
        const double impulse = p.normal_mass * (target - vn);
        if (x.impact_normal == 0.0) x.impact_vn = vn; // the approach, for the in-step shift
        x.impact_normal += impulse;
        apply(A, va, p.ra, -impulse * n);
        apply(B, vb, p.rb, impulse * n);
        any = true;

        // Friction during the impact, within this impact's Coulomb cone.
        friction_at_point(c, p, A, B, x.impact_normal, x.impact_friction, va, vb);
    }
    store(s, c.a, c.move_a, va);
    store(s, c.b, c.move_b, vb);
    return any;
}

bool impact_in_step(const SolverManifold& c, const SolverPoint* points, const PointAux* aux,
                    const SolverBodies& bodies, const SolverContext& ctx, State& s, double& ds) {
    int hits = 0, k = 0;
    for (int j = 0; j < c.count; ++j)
        if (aux[j].impact_normal != 0.0) ++hits, k = j;
    if (hits != 1) return false;
    const SolverPoint& p = points[k];
    const PointAux& x = aux[k];
    const double an = normal_acceleration(c, bodies);
    const double h = ctx.step_h;
    const double s0 = std::max(x.separation0, 0.0), vn = x.impact_vn;
    const double speed = std::sqrt(std::max(vn * vn - 2.0 * an * s0, 0.0));
    const double t_hit = 2.0 * s0 / (-vn + speed);
    // Counted as an impact but arriving after this step (within kArrival of the surface at its
    // end): a bounce "at t_hit" would end the step with u + a (h - t_hit), faster than u when
    // t_hit > h, energy from nowhere (measured: 0.05 m/s arrivals leaving at 0.07 m/s at dt 1e-3).
    // The energy-exact velocity resolve_impacts() set stands, with no shift.
    if (t_hit > h) return false;
    const double tau = h - t_hit;
    const double u = c.restitution * speed;
    // Velocity now such that the step ends with u + a tau, as after a bounce at t_hit.
    const BodyView A = body_a(c), B = body_b(c);
    Velocity va = load(s, c.a), vb = load(s, c.b);
    const double now = c.normal.dot(relative_velocity(va, vb, p.ra, p.rb));
    const double target = u - an * t_hit;
    const double impulse = p.normal_mass * (target - now);
    apply(A, va, p.ra, -impulse * c.normal);
    apply(B, vb, p.rb, impulse * c.normal);
    store(s, c.a, c.move_a, va);
    store(s, c.b, c.move_b, vb);
    const double s_true = std::max(u * tau + 0.5 * an * tau * tau, 0.0);
    const double s_early = s0 + target * h + 0.5 * an * h * h;
    ds = s_true - s_early;
    return true;
}

// Sweeps in colour order, on the velocities at the start of the step, until no impact is left.
// After the first sweep a constraint is looked at again only if one of its bodies changed
// velocity since it last was (its own impulse included): with the same velocities it would find
// the same nothing, so skipping it changes no bit. (Skipping, in the first sweep too, constraints
// whose bodies were too slow for any point to approach at the threshold saved nothing measurable
// in the sphere rain: its impacts stage went from 4.9 to 4.7 % of the step.)
void ContactStage::impacts(const Model& m, State& s, ThreadPool& pool) {
    Stopwatch clock;
    impact_flags_.assign(pool.size(), 0);
    impact_changed_.assign(m.body_count(), -1);
    impact_seen_.resize(manifolds_.size());
    const auto constraints = static_cast<std::int64_t>(manifolds_.size());
    stats_.impacts = 0;
    for (int sweep = 0; sweep < kImpactSweeps; ++sweep) {
        std::fill(impact_flags_.begin(), impact_flags_.end(), 0);
        // Within a colour no two constraints share a moving body; the overflow colour runs in
        // slot order on one thread, so "changed after it was looked at" is exact there too.
        for_each_colour(pool, [&](int begin, int end, int worker) {
            for (int k = begin; k < end; ++k) {
                const SolverManifold& c = manifolds_[k];
                if (sweep > 0 && impact_changed_[c.a] < impact_seen_[k] &&
                    impact_changed_[c.b] < impact_seen_[k])
                    continue;
                const std::int64_t now = sweep * constraints + k;
                impact_seen_[k] = now;
                if (!resolve_impacts(c, &points_[c.first], &aux_[c.first], bodies_, ctx_, s))
                    continue;
                impact_flags_[worker] = 1;
                if (c.move_a) impact_changed_[c.a] = now;
                if (c.move_b) impact_changed_[c.b] = now;
            }
        });
        if (std::find(impact_flags_.begin(), impact_flags_.end(), 1) == impact_flags_.end()) break;
        ++stats_.impacts;
    }
    shifted_.clear();
    if (stats_.impacts > 0) plan_impact_shifts(m, s);
    profile_.impacts = clock.lap();
}

// Impacts that happened in isolation (one impacting point, neither body in another impact) move
// to the moment of contact: impact_in_step() sets the velocity now, and the position change waits
// in shift_ until the substeps are done.
void ContactStage::plan_impact_shifts(const Model& m, State& s) {
    impact_count_.assign(m.body_count(), 0);
    for (const SolverManifold& c : manifolds_) {
        bool hit = false;
        for (int k = 0; k < c.count; ++k) hit |= aux_[c.first + k].impact_normal != 0.0;
        if (!hit) continue;
        impact_count_[c.a] += c.move_a;
        impact_count_[c.b] += c.move_b;
    }
    shift_.resize(m.body_count());
    for (const SolverManifold& c : manifolds_) {
        if ((c.move_a && impact_count_[c.a] != 1) || (c.move_b && impact_count_[c.b] != 1))
            continue;
        double ds = 0.0;
        if (!impact_in_step(c, &points_[c.first], &aux_[c.first], bodies_, ctx_, s, ds)) continue;
        const double ma = c.move_a ? m.inv_mass[c.a] : 0.0;
        const double mb = c.move_b ? m.inv_mass[c.b] : 0.0;
        if (c.move_a) shift_[c.a] = -ds * ma / (ma + mb) * c.normal, shifted_.push_back(c.a);
        if (c.move_b) shift_[c.b] = ds * mb / (ma + mb) * c.normal, shifted_.push_back(c.b);
    }
}

// After the substeps: the isolated impacts' bodies end where a bounce inside the step puts them.
void ContactStage::apply_impact_shifts(State& s) {
    for (int i : shifted_) s.x[i] += shift_[i];
}

} // namespace tumble::physics
