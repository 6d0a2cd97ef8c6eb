#pragma once
// Contact constraints and the sequential-impulse kernels that solve them (Box2D v3's soft step,
// in three dimensions with two friction directions). See step.cpp for where each runs.
//
// Unknowns: per contact point the normal impulse lambda_n >= 0 and the friction impulse
// (lambda_1, lambda_2) with |lambda_t| <= mu lambda_n (Coulomb's cone). Projected Gauss-Seidel:
// one constraint at a time, the impulse that zeroes its velocity error is computed with the
// effective mass and clamped to its bounds; repeating converges to the joint solution, and
// starting from last step's impulses (warm starting) makes one sweep per substep enough for
// resting contact.
//   relative velocity at a point:  v_rel = vB + wB x rB - vA - wA x rA, vn = n . v_rel
//   effective mass along a unit d: 1/k, k = mA^-1 + mB^-1 + (rA x d) . IA^-1 (rA x d) + (B)
//   impulse P = lambda d applied as vA -= P/mA, wA -= IA^-1 (rA x P), and + for B.
//
// Soft contact (Catto, "Solver2D", 2024): overlap s < 0 is pushed out as a damped spring of
// stiffness k = m_eff omega^2 (omega = 2 pi hertz) rather than by a Baumgarte fraction of it. For
// the implicit (backward Euler) spring-damper, with zeta the damping ratio and h the substep:
//   a1 = 2 zeta + h omega,  a2 = h omega a1,  a3 = 1 / (1 + a2)
//   bias_rate = omega / a1, mass_scale = a2 a3, impulse_scale = a3
//   delta_lambda = -m_eff (mass_scale (vn + bias_rate s)) - impulse_scale lambda
// which is stable for any stiffness. The push-out speed bias_rate s is capped at max_push_speed.
// A "relax" sweep after the positions move re-solves with no bias, removing the push-out
// velocity again: overlap is corrected in position without the correction becoming kinetic
// energy (the split-impulse effect, as in Box2D v3). A speculative point (s > 0) only limits the
// approach speed to vn >= -s / h, so that the gap closes exactly at the end of the substep.
#include "physics/model.h"
#include "physics/state.h"

#include <cstdint>
#include <vector>

namespace tumble::physics {

struct Softness {
    double bias_rate = 0.0, mass_scale = 1.0, impulse_scale = 0.0;
};
Softness make_softness(double hertz, double zeta, double h);

// The tangential effective mass of a contact point: K^-1 (k11, k12, k22 of the inverse of the 2x2
// matrix K in the tangents t1, t2) and 1 / (largest eigenvalue of K).
struct TangentMass {
    double k11, k12, k22, scalar;
};

// A contact point as every sweep reads it (120 bytes); what only the step's other stages read is
// in PointAux, at the same index, so that a sweep streams no more than it uses.
struct SolverPoint {
    Vec3 ra, rb;            // anchors from the centres of mass, world, turned with the bodies
    double base_separation; // s0 - n.(rb0 - ra0): with the bodies' motion d, s = base + n.(dB +
                            // rB - dA - rA) at the current anchors
    double normal_mass;     // 1/k along n, at the current anchors and orientations
    TangentMass tangent_mass;
    double normal_impulse; // accumulated over the step (warm-started)
    double friction_impulse[2];
};

// The rest of a contact point: read when the anchors turn (follow_manifold), by the impacts and
// by the effort's estimate of loads.
struct PointAux {
    Vec3 core_a, core_b;  // what turns with each body: the anchor at the start of the step,
                          // moved by a capsule's radius onto its core segment
    double separation0;   // s0, m
    double impact_normal; // impact pass: impulses of this step's impacts
    double impact_friction[2];
    double impact_vn; // the normal velocity the first impact met
};

struct SolverManifold {
    int a, b;                          // bodies
    std::uint8_t move_a, move_b;       // 1: awake dynamic (takes impulses); 0: static or asleep
    std::uint8_t rotates_a, rotates_b; // the anchors turn with the body (not for a sphere)
    Vec3 normal, t1, t2;               // unit, normal from a to b
    double friction, restitution;
    // The bodies' mass properties as the kernels see them (contact_kernels.h, BodyView), kept in
    // the constraint as Box2D v3 does, so that a sweep reads each body's velocities and nothing
    // else of it: 0 for a body that does not move; I_w^-1 by pointer for a body that is not
    // isotropic (turned with it, ContactStage::track_motion), else null and inv_i = 1/I.
    double inv_mass_a, inv_mass_b, inv_i_a, inv_i_b;
    const Mat3 *inertia_a, *inertia_b;
    int first, count; // points[first .. first + count)
    int cache;        // manifold index in the contact cache (impulse write-back)
};

// Per body, what every sweep reads and writes, in one record (Box2D v3's b2BodyState): the
// velocities, copied from the State before a solve or relax and back after it
// (contact_substeps.cpp), and the motion since the start of the step. A static or sleeping body
// keeps v = w = delta = 0.
struct SolverBody {
    Vec3 v, w;
    Vec3 delta; // motion of the centre of mass since the start of the step, at the last update
};

// Per body, indexed by body. Set for the awake bodies at the start of the step
// (contact_prepare.cpp); turn and inv_inertia then follow the bodies in constraints through the
// substeps (updated before each predict and relax, ContactStage::track_motion in
// contact_substeps.cpp), as does SolverBody::delta.
struct SolverBodies {
    std::vector<Mat3> inv_inertia; // world I_w^-1, at the orientation of the last update
    std::vector<double> inv_i;     // isotropic bodies: 1/I (then inv_inertia is not used)
    std::vector<std::uint8_t> isotropic;
    std::vector<double> inv_mass;
    std::vector<Vec3> x0; // centre of mass at the start of the step
    std::vector<Quat> q0;
    std::vector<Mat3> turn;            // rotation since the start of the step, at the last update
    std::vector<std::uint8_t> rotates; // anchors turn with the body (not for spheres)
    std::vector<double> rounding;      // m: a capsule's radius (its anchors turn about its core)
    std::vector<Vec3> accel;           // F / m, m/s^2 (gravity and applied force)
    std::vector<Vec3> ang_accel;       // I_w^-1 tau_applied, rad/s^2
};

struct SolverContext {
    Softness soft;               // contacts between two movable bodies
    Softness soft_static;        // against a static or sleeping body: twice the frequency
    double h = 0.0, inv_h = 0.0; // substep
    double step_h = 0.0;         // the whole step (impacts look ahead over it)
    double max_push_speed = 3.0;
    double restitution_threshold = 0.5;
};

// Effective masses, tangents, anchors; warm-start impulses already in `points`.
void prepare_manifold(SolverManifold& c, SolverPoint* points, PointAux* aux,
                      const SolverBodies& bodies, const State& state);

// Anchors turned with their bodies (r = turn r0) and the effective masses recomputed with them and
// the current I_w^-1: impulses go where the contact now is, through the inertia the body now has.
// No-op unless a body of the manifold turns.
void follow_manifold(const SolverManifold& c, SolverPoint* points, const PointAux* aux,
                     const SolverBodies& bodies);

void warm_start(const SolverManifold& c, const SolverPoint* points, SolverBody* solver_bodies);

// One Gauss-Seidel sweep over one manifold: normal (soft if use_bias) then friction.
void solve_manifold(const SolverManifold& c, SolverPoint* points, const SolverContext& ctx,
                    bool use_bias, SolverBody* solver_bodies);

// Impacts (restitution): see contact_impacts.cpp. Returns true if any impulse was applied.
bool resolve_impacts(const SolverManifold& c, const SolverPoint* points, PointAux* aux,
                     const SolverBodies& bodies, const SolverContext& ctx, State& state);

// After the impacts, for a manifold with one impacting point whose bodies had no other impact:
// moves the bounce from the start of the step to the moment of contact. Sets the normal velocity
// and writes the change `ds` of the separation to apply at the end of the step; false if the
// manifold does not qualify.
bool impact_in_step(const SolverManifold& c, const SolverPoint* points, const PointAux* aux,
                    const SolverBodies& bodies, const SolverContext& ctx, State& state, double& ds);

} // namespace tumble::physics
