// splitting4_exact: Suzuki's fourth-order five-stage composition (Phys. Lett. A 146, 1990; as in
// integrator_splitting4.cpp) of `splitting_exact`:
//
//   S4(h) = S(g h) S(g h) S((1 - 4 g) h) S(g h) S(g h),   g = 1 / (4 - 4^(1/3)) = 0.41449
//
// with S the kick, exact free flow, kick step. sum g_i = 1 and sum g_i^3 = 0 cancel the h^3 term
// of the symmetric S, so S4 is of order 4 (the middle substep, -0.658 h, runs backwards).
// Order: 4.
// Conserves: what `splitting_exact` conserves; exact without torque, like it.
// Known failure: five exact free flows per step, 5.2 times the cost of a `splitting4` step. Under
// the study's torque that does not pay (with half of splitting4's steps it errs three times
// more); with 1e-4 of it, a quarter of the steps err five times less, about twice as accurate at
// equal cost (SplittingExact.Splitting4ExactPaysOnlyUnderWeakTorques; docs/integrators.md).
#include "physics/model.h"
#include "physics/passes.h"
#include "physics/splitting.h"
#include "physics/state.h"

namespace tumble::physics {

void integrate_splitting4_exact(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies)
        suzuki_composition(h, [&](double tau) { splitting_exact_step(m, s, i, tau, loads); });
}

} // namespace tumble::physics
