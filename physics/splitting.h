#pragma once
// The one step of `splitting` (integrator_splitting.cpp), shared with `splitting4`, which composes
// it. Internal to physics: not part of the integrator registry.
#include "physics/model.h"
#include "physics/state.h"

namespace tumble::physics {

// Exact flows of the split kinetic energy for time h: moves the mass-frame orientation q and the
// body momentum m = I w_b of a torque-free body with principal moments I (inverse inv_I).
void free_rotation_split(const Vec3& I, const Vec3& inv_I, Quat& q, Vec3& m, double h);

// One kick-drift-kick step of body i; `loads` is loads_on(model).
void splitting_step(const Model& model, State& state, int body, double h, bool loads);

} // namespace tumble::physics
