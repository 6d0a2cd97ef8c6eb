// exact: each body's exact motion over the step, for scenes without applied torques. The rotation
// is the torque-free flow of Euler and Jacobi (free_rotation.h, derived in
// docs/exact-solutions.md) and the translation the closed form under constant loads:
//
//   x' = x + h v + h^2/2 a,   v' = v + h a,       a = sum F / m = s g + F_applied / m
//   (q', w') = the torque-free motion from (q, w) after time h:
//     w = 0:                    nothing turns (q, w kept bit for bit);
//     isotropic body:           q' = exp(h w) (x) q, w' = w (I_w w = I w: w is constant);
//     two equal moments, or m along a principal axis: regular precession,
//                               R' = exp(h [L]x / I_t) R exp(lambda h [e_s]x) (trigonometric);
//     three distinct moments:   m(h) by Jacobi's sn, cn, dn and the angle about L by the elliptic
//                               integral of the third kind, from the invariants E and |L| of
//                               (q, w) computed afresh every step.
//
// Order: none. Nothing is truncated, so on the scenes it accepts the error at any step h is the
// round-off of the steps taken; the registry reports kExactOrder (0, integrator.h), and the study
// shows no fitted order for it. Measured against the long-double reference written in
// tests/physics/exact_integrator_test.cpp over 6 s at h = 0.1 s and 1 s: 7e-12 rad on the
// flipping book, 6e-15 on a symmetric top, 3e-13 on a thin rod, 6e-13 on a 1000 rad/s spin (at
// 1000 rad a step), 1.6e-10 at 1e-13 from the separatrix.
// Conserves: energy and world angular momentum to round-off, with no drift: every step follows
// the motion with the state's own E and L, so their error is a random walk of ~1e-16 per step
// (5.9e-14 and 8.9e-14 after 1e5 steps; free_rotation.h, "Rounding", says how bias is avoided;
// the conversions w -> m -> w go through rigid_body.h's rotate(), as in `splitting`).
// Torques: build_model() refuses a scene with an applied torque for `exact` (ModelError naming
// the body and its `torque`; `splitting_exact` takes torques). Gravity and applied forces are
// exact: they do not turn a body.
// Contacts: allowed. The contact stage changes v and w by impulses between and within steps and
// calls the integrator over each substep; between the impulses the flow is still exact, so the
// error of a contact scene is the contact stage's own (first order, docs/contacts.md), as with
// every integrator; `exact` only removes the integrator's share.
// The separatrix (|L|^2 = 2 E I_mid, where the oracle of physics/exact refuses to answer): the
// flow is computed in the complementary parameter mc = 1 - k^2 from the exactly formed
// |L|^2 - 2 E I_mid, so it stays accurate as mc -> 0 and takes the separatrix motion itself
// (sn = tanh, cn = dn = sech) at mc = 0. No step throws and nothing is replaced by another method.
// What no double-precision method escapes is the conditioning there: the time between flips grows
// like ln(1 / mc), so the round-off of E and |L| (1e-16 relative per step) moves later flips by
// about 1e-16 / mc of a period (docs/integrators.md measures it from 1e-9 to 1e-15 of it).
// Cost: one FreeRotation per tumbling body and step: an arithmetic-geometric mean ladder, one R_F,
// two R_J, two sn cn dn and a few 3x3 products, nothing allocated: 805 ns a body-step, 5.6 times
// `splitting` (bench/results/vm-xeon). Isotropic bodies cost one exponential map, as in every
// method.
// Known failure: the cost per step; it pays where the step can be long (torque-free flight: one
// step per frame, or per output sample) or the error must be round-off.
#include "physics/compensated.h"
#include "physics/forces.h"
#include "physics/free_rotation.h"
#include "physics/model.h"
#include "physics/passes.h"
#include "physics/splitting.h"
#include "physics/state.h"

namespace tumble::physics {

void exact_free_rotation(const Model& m, State& s, int i, double h) {
    if (s.w[i] == Vec3::Zero()) return; // at rest: the flow is the identity
    if (!anisotropic(m, i)) {
        s.q[i] = (quat_exp(h * s.w[i]) * s.q[i]).normalized(); // exact: w is constant
        return;
    }
    const FreeState next = FreeRotation(m.inertia[i], s.q[i], s.w[i]).at(h);
    s.q[i] = next.q;
    s.w[i] = next.w;
}

void integrate_exact(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies) {
        if (loads) {
            const Vec3 a = m.inv_mass[i] * net_force(m, i);
            add_compensated(s.x[i], s.x_carry[i], h * s.v[i] + (0.5 * h * h) * a);
            s.v[i] += h * a;
        } else {
            add_compensated(s.x[i], s.x_carry[i], h * s.v[i]);
        }
        exact_free_rotation(m, s, i, h);
    }
}

} // namespace tumble::physics
