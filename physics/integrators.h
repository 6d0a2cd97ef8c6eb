#pragma once
// One function per named integrator, each in integrator_<name>.cpp. Each advances every dynamic
// body of `state` by one step h under the loads of forces.h. step() dispatches to them once per
// step (a switch, not a virtual call per body).
#include "physics/model.h"
#include "physics/state.h"

namespace tumble::physics {

void integrate_euler(const Model& model, State& state, double h);
void integrate_euler_momentum(const Model& model, State& state, double h);
void integrate_symplectic_euler(const Model& model, State& state, double h);
void integrate_implicit_gyro(const Model& model, State& state, double h);
void integrate_rk4(const Model& model, State& state, double h);
void integrate_splitting(const Model& model, State& state, double h);
void integrate_midpoint(const Model& model, State& state, double h);
void integrate_splitting4(const Model& model, State& state, double h);

} // namespace tumble::physics
