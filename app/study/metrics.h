#pragma once
// Errors of a run against a reference motion, and the reference motion itself at the sample times
// t_j = j T / kSamples (j = 0 .. kSamples) of a problem.
//   position          max over dynamic bodies of |x - x_ref|, m
//   orientation       max over dynamic bodies of the angle of R_ref^T R, rad (in [0, pi])
//   angular velocity  max over dynamic bodies of |w - w_ref| / |w_ref| (|w - w_ref| in rad/s
//                     for a body whose reference is not turning)
//   energy            |E - E_ref| / |E_ref|, E = T_lin + T_rot + V of the whole scene
//   momentum          |L - L_ref| / |L_ref|, L the world angular momentum about the origin
// E_ref and L_ref come from the reference state (they change under loads), through the same
// physics::diagnose() as the run's, so both sides are measured the same way.
#include "app/study/study.h"
#include "physics/diagnostics.h"
#include "physics/model.h"
#include "physics/state.h"

#include <vector>

namespace tumble::app::study {

struct Reference {
    std::vector<physics::State> states; // kSamples + 1 states, at t_j
    std::vector<physics::Diagnostics> diagnostics;
};

// The model and initial state of a problem stepped with `integrator` at step dt.
struct Setup {
    physics::Model model;
    physics::State state;
};
Setup make_setup(const Problem& p, physics::Integrator integrator, double dt);

// The reference motion of a problem at its sample times: exact oracles, or a converged run of the
// registry's highest-order integrator at (finest grid step) / p.reference_refine.
Reference make_reference(const Problem& p, bool quick);

Errors measure(const physics::Model& model, const physics::State& run, const physics::State& ref,
               const physics::Diagnostics& ref_diag);

void keep_max(Errors& max, const Errors& e);

// The largest initial |w| over the problem's dynamic bodies, rad/s (the h|w| column).
double largest_spin(const Problem& p);

} // namespace tumble::app::study
