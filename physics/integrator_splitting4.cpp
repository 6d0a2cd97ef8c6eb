// splitting4: a fourth-order composition of `splitting`, Suzuki's five-stage "fractal" (Suzuki,
// Phys. Lett. A 146, 1990; the same construction as Yoshida's, Phys. Lett. A 150, 1990):
//
//   S4(h) = S(g h) S(g h) S((1 - 4 g) h) S(g h) S(g h),   g = 1 / (4 - 4^(1/3)) = 0.41449
//
// where S is the second-order, time-symmetric `splitting` step (kicks included). A symmetric
// composition whose weights satisfy sum g_i = 1 and sum g_i^3 = 0 cancels the h^3 error term of S,
// so S4 is of order 4 and still time-symmetric and symplectic; the middle substep (-0.658 h) runs
// backwards. Of the two classic choices we measured Yoshida's three-stage triple jump
// (g = 1.3512, -1.7024) to be 33 times less accurate at 3/5 of the cost: at equal cost the
// five-stage version is about 4 times more accurate (docs/integrators.md).
// Order: 4.
// Conserves: what `splitting` conserves, the same way: world angular momentum without torque to
// round-off, bounded energy error without drift; exact for isotropic bodies and symmetric tops.
// Known failure: five times the cost of `splitting`, so it only pays when the error wanted is
// small (below about 1e-6 rad per second at h |w| < 0.1); round-off of the five substeps puts its
// floor near 1e-11.
#include "physics/model.h"
#include "physics/passes.h"
#include "physics/splitting.h"
#include "physics/state.h"

namespace tumble::physics {

void integrate_splitting4(const Model& m, State& s, double h, std::span<const int> bodies) {
    const bool loads = loads_on(m);
    for (int i : bodies)
        suzuki_composition(h, [&](double tau) { splitting_step(m, s, i, tau, loads); });
}

} // namespace tumble::physics
