// splitting_exact: Strang splitting of the loads from the exact free flow (Celledoni, Fasso,
// Safstrom and Zanna, "The exact computation of the free rigid body motion and its use in
// splitting methods", SIAM J. Sci. Comput. 30(4), 2008). With H = T + V, T the kinetic energy and
// V the potential of the constant loads, the flow of V is a kick and the flow of T is the free
// motion, which `exact` computes in closed form (free_rotation.h):
//
//   v += h/2 a,   L += h/2 tau  (world; w += I_w^-1 (h/2 tau))      half kick of the loads
//   x += h v;     (q, w) <- the exact torque-free motion for time h   free flow
//   v += h/2 a,   L += h/2 tau                                        half kick
//
// This is `splitting` (integrator_splitting.cpp) with its approximate free flow (three exact
// rotations of a split kinetic energy) replaced by the exact one.
// Order: 2 (a symmetric composition of exact flows); its error comes only from the loads not
// commuting with the free motion, so it is proportional to the torque: without torque every
// step is exact (the kicks change v alone, and x += h v after the half kick is x + h v + h^2/2 a:
// the same bits as `exact` up to rounding).
// Conserves: without torque, what `exact` conserves (energy and L to round-off, no drift); under a
// constant torque, L changes by exactly h tau per step (the kicks add it, the free flow keeps L),
// and as a symplectic (Lie-Poisson) map it has no energy drift where the loads derive from a
// potential.
// Contacts: as `exact` (the flow between impulses is exact; the contact stage's error remains).
// Known failure: the O(h^2) error under torque, with an error constant set by the torque rather
// than by the tumbling (measured against `splitting` on the torqued book in docs/integrators.md);
// each step costs what an `exact` step costs.
#include "physics/compensated.h"
#include "physics/model.h"
#include "physics/passes.h"
#include "physics/splitting.h"
#include "physics/state.h"

namespace tumble::physics {

void splitting_exact_step(const Model& m, State& s, int i, double h, bool loads) {
    if (loads) load_half_kick(m, s, i, h);
    add_compensated(s.x[i], s.x_carry[i], h * s.v[i]);
    exact_free_rotation(m, s, i, h);
    if (loads) load_half_kick(m, s, i, h);
}

void integrate_splitting_exact(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies) splitting_exact_step(m, s, i, h, loads);
}

} // namespace tumble::physics
