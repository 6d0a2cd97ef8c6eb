#pragma once
// The one step of `splitting` (integrator_splitting.cpp), shared with `splitting4`, which composes
// it, and the exact-flow splittings (integrator_splitting_exact.cpp), which share its kick.
// Internal to physics: not part of the integrator registry.
#include "physics/model.h"
#include "physics/state.h"

namespace tumble::physics {

// Exact flows of the split kinetic energy for time h: moves the mass-frame orientation q and the
// body momentum m = I w_b of a torque-free body with principal moments I (inverse inv_I).
void free_rotation_split(const Vec3& I, const Vec3& inv_I, Quat& q, Vec3& m, double h);

// Half a step of the constant loads: v += h/2 sum F / m, and L += h/2 sum tau in the world, that
// is w += I_w^-1 (h/2 sum tau).
void load_half_kick(const Model& model, State& state, int body, double h);

// One kick-drift-kick step of body i; `loads` is loads_on(model).
void splitting_step(const Model& model, State& state, int body, double h, bool loads);

// The exact torque-free flow of body i's (q, w) for time h (integrator_exact.cpp).
void exact_free_rotation(const Model& model, State& state, int body, double h);

// One kick, exact free flow, kick step of body i (integrator_splitting_exact.cpp).
void splitting_exact_step(const Model& model, State& state, int body, double h, bool loads);

// Suzuki's fourth-order composition of a time-symmetric second-order step S (integrator_splitting4
// .cpp derives it): S(g h) S(g h) S((1 - 4 g) h) S(g h) S(g h), g = 1 / (4 - 4^(1/3)). `step(tau)`
// performs S for time tau; shared by splitting4 and splitting4_exact.
template <class Step>
inline void suzuki_composition(double h, Step&& step) {
    const double g = 0.4144907717943757; // 1 / (4 - 4^(1/3))
    const double middle = 1.0 - 4.0 * g;
    step(g * h);
    step(g * h);
    step(middle * h);
    step(g * h);
    step(g * h);
}

} // namespace tumble::physics
