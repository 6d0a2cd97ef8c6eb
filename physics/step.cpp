// One step of the simulation, assembled from what the scene contains (Model::passes).
//
// The named integrator is the function in its row of the registry (integrator.h), called once per
// step or substep over the whole list of bodies.
//
// A scene whose shapes can never touch (can_touch.h: one body, none dynamic, or bodies whose free
// flight keeps them apart) runs only the named integrator over the step h, then the finite check.
// Nothing else is built or run: no broad phase, no buffers, no threads ("model only what a scene
// requires"; `tumble explain` says which).
//
// A scene with contacts runs the contact stage (contact_stage.h), which wraps the integrator in
// the soft step of Box2D v3 (Catto, "Solver2D", 2024). ContactStage::step (contact_stage.cpp) is
// this list, and each stage lives in the file named after it:
//
//   1. find     poses and bounding boxes grown by the distance each body can move in h; uniform-
//               grid broad phase (broadphase.h); narrow phase (collide.h) with speculative
//               points up to `margin = 1 cm + h |relative speed|` apart, so that anything that
//               can meet within the step is a contact now: nothing tunnels through anything as
//               long as it moves less than its own size in a step (a speed-aware bound, not a
//               swept time-of-impact search; a 50 m/s ball against a 1 cm wall is a test).
//               Points keep feature ids, and last step's impulses carry over to the same ids
//               (contact_find.cpp).
//   2. wake     an awake body touching a sleeping one wakes the sleeper's island
//               (contact_wake.cpp).
//   3. prepare  mass properties and loads at the start of the step; graph colouring (no colour
//               holds two constraints on one moving body) fixes the solve order; anchors,
//               effective masses, tangents; the substep's soft-contact coefficients
//               (contact_prepare.cpp).
//   4. impacts  restitution: approaching points that close within the step get pairwise
//               Newton collisions, swept until no impact is left, energy-consistent with the bounce
//               happening inside the step; an isolated bounce is moved to its moment of contact
//               once the substeps are done (contact_impacts.cpp).
//   5. substeps the effort of each island of bodies in contact (contact_islands.cpp,
//               contact_effort.cpp): n substeps of h' = h / n, the fewest that keep its
//               contacts' sag within the contact tolerance and its bodies' turn within 0.1 rad,
//               and 1-3 solve and 1-2 relax sweeps by what its constraints link; islands with
//               the same n are stepped together (contact_substeps.cpp), each substep:
//        a. predict    v += h' F/m, w += h' I^-1 tau on bodies in contact; anchors and
//                      effective masses follow the bodies' turn since the step's start
//        b. solve      warm start, then the Gauss-Seidel sweeps (contact_sweeps.cpp): soft
//                      non-penetration (pushes overlap out as a stiff damped spring), Coulomb
//                      friction with two tangents clamped to the disc mu lambda_n
//                      (contact_solver.h)
//        c. integrate  the named integrator over h' for the group's bodies (rotation,
//                      gyroscopic term, free flight); bodies in contact then move by
//                      x += h' v_solved
//        d. relax      the relax sweeps without the push-out bias, so position correction
//                      never becomes kinetic energy
//               Bodies in no constraint fly over the whole step h. A scene that sets
//               world.substeps or world.iterations fixes the effort instead: n and the sweeps
//               alike in every island, every awake body integrated at each substep (the stage
//               before issue 28, bit for bit).
//   6. store    impulses into this step's contacts, which become the State's contact cache (the
//               warm start of the next step; contact_store.cpp).
//   7. sleep    islands slow for long enough fall asleep (contact_sleep.cpp).
//
// After either, a scene with dampers (damper.h) runs their stage over the whole step h: the coupling
// torques, split from the rest at first order.
//
// With no constraint to solve (every contact between bodies that cannot move, or none), 4 and 5
// are replaced by the integrator over the whole step h for every awake body (free flight, in
// contact_substeps.cpp): the same bits as a scene without contacts.
//
// How contacts meet the integrators (5a-5c). The solver computes impulses from predicted
// velocities v + h' F/m, the velocities the step would end with, and the integrator then adds the
// loads itself, so every named integrator runs unchanged and keeps doing the rotation, the
// gyroscopic torque and the free flight of bodies not in contact. One thing cannot be left to it:
// an impulse applied at the start of a substep followed by constant gravity moves a body by
// h' (v + dv) + beta h'^2 g, where beta depends on the integrator (0 for explicit Euler, 1/2 for
// rk4 and the splittings, 1 for symplectic Euler), while the constraint assumed x += h' v_end.
// A box resting on a ramp would creep by 1/2 g sin(a) h' per substep with rk4, about 7 cm in
// 10 s. So for bodies in contact the translation is the symplectic x += h' v_solved, exactly what
// the constraints were solved for, and resting stays resting with every integrator.
//
// Sleeping bodies are skipped: the integrator still visits them (its interface steps every
// dynamic body), and their pose is restored after it, with v = w = 0; they are never solved.
//
// Threads (step(model, state, workspace) with a workspace of 2 or more, from
// world.parallel_min_bodies dynamic bodies on): the broad and narrow phases, preparation, each
// colour of each sweep and the integrator calls are split into fixed ranges per worker; every
// worker writes only its own outputs (an integrator updates each body from that body's state
// alone), so states are bit-identical for any thread count.
#include "physics/step.h"

#include "physics/damper.h"
#include "physics/integrator.h"

#include <cmath>

namespace tumble::physics {

namespace {

// What of dynamic body i is not finite, or nullptr: its state, or the two terms of its kinetic
// energy T = 1/2 m |v|^2 + 1/2 w . I_w w, which overflow long before v and w do (|v| > 1e154).
// The rotational term is bounded by I_max |w|^2, two multiplications instead of a rotation.
const char* not_finite(const Model& m, const State& s, int i) {
    if (!all_finite(s.x[i])) return "position";
    if (!all_finite(s.q[i])) return "orientation";
    if (!all_finite(s.v[i])) return "velocity";
    if (!all_finite(s.w[i])) return "angular velocity";
    if (!std::isfinite(m.mass[i] * s.v[i].squaredNorm())) return "kinetic energy m |v|^2";
    if (!std::isfinite(m.inertia[i].maxCoeff() * s.w[i].squaredNorm()))
        return "rotational kinetic energy I |w|^2";
    return nullptr;
}

} // namespace

void check_finite(const Model& m, const State& s) {
    for (int i : m.dynamic_bodies) {
        if (const char* bad = not_finite(m, s, i))
            throw DivergenceError(i, s.step, bad,
                                  "body " + std::to_string(i) + ": " + bad +
                                      " is not finite after step " + std::to_string(s.step) +
                                      " (the integrator diverged, or the scene's speeds are "
                                      "too large for a double; try a smaller dt or another "
                                      "integrator)");
    }
}

namespace {

StepWorkspace& thread_workspace() {
    thread_local StepWorkspace workspace(1);
    return workspace;
}

} // namespace

StepWorkspace::StepWorkspace(int threads) : pool(threads) {}

void step(const Model& m, State& s) {
    step(m, s, thread_workspace());
}

void step(const Model& m, State& s, StepWorkspace& workspace) {
    // The named integrator: its row of the registry (integrator.h), one call per step or substep.
    const IntegrateFn integrate = integrator_info(m.integrator).integrate;
    if (m.passes.contacts)
        workspace.contacts.step(m, s, integrate, workspace.pool);
    else
        integrate(m, s, m.dt, m.dynamic_bodies);
    if (m.passes.dampers) apply_dampers(m, s, m.dt); // damper.h: after the rest, first order
    ++s.step;
    check_finite(m, s);
}

} // namespace tumble::physics
