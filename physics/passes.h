#pragma once
// "Model only what a scene requires": build_model() decides once which passes the step needs
// (Model::passes) and which bodies may skip the gyroscopic term (Model::isotropic). The
// integrators ask through these helpers, so that forcing the full pipeline reaches every branch.
#include "physics/model.h"

namespace tumble::physics {

// Some dynamic body feels a constant force or torque: the integrators' velocity kicks run.
// Off (no gravity, no applied loads): v and w change only through the gyroscopic term.
inline bool loads_on(const Model& m) {
    return m.passes.gravity || m.passes.applied_loads;
}

// Body i is stepped with its full inertia I_w = R I_body R^T: its moments differ, or the full
// pipeline is forced. An isotropic body has I_w = I 1, so w x I_w w = I (w x w) = 0 exactly and
// I_w^-1 is a scalar: the gyroscopic term and every rotation into the body frame are skipped.
// Exact, not an approximation.
inline bool anisotropic(const Model& m, int i) {
    return m.all_passes || !m.isotropic[i];
}

// The full pipeline: turns on every pass the integrators know (gravity, applied loads,
// gyroscopic) and the contact stage, and sets Model::all_passes, so that no body takes a shortcut.
// Results then agree with the assembled step to round-off (tests/physics/passes_test.cpp says how
// closely and why). The contact stage of a scene whose shapes cannot touch (can_touch.h) finds no
// contact point and hands the whole step to the integrator: the same bits, plus its cost.
void force_all_passes(Model& m);

} // namespace tumble::physics
