#pragma once
// One function per named integrator, each in integrator_<name>.cpp. Each advances every dynamic
// body of `state` by one step h under the loads of forces.h. step() dispatches to them once per
// step (a switch, not a virtual call per body).
#include "physics/model.h"
#include "physics/state.h"

namespace tumble::physics {

void integrate_rk4(const Model& model, State& state, double h);

} // namespace tumble::physics
