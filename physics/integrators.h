#pragma once
// One function per named integrator, each in integrator_<name>.cpp. Each advances the dynamic
// bodies listed in `bodies` by one step h under the loads of forces.h, each body's update reading
// and writing only that body's state (so a list may be split between threads). step() dispatches
// to them once per step (a switch, not a virtual call per body).
#include "physics/model.h"
#include "physics/state.h"

#include <span>

namespace tumble::physics {

void integrate_euler(const Model& model, State& state, double h, std::span<const int> bodies);
void integrate_euler_momentum(const Model& model, State& state, double h,
                              std::span<const int> bodies);
void integrate_symplectic_euler(const Model& model, State& state, double h,
                                std::span<const int> bodies);
void integrate_implicit_gyro(const Model& model, State& state, double h,
                             std::span<const int> bodies);
void integrate_rk4(const Model& model, State& state, double h, std::span<const int> bodies);
void integrate_splitting(const Model& model, State& state, double h, std::span<const int> bodies);
void integrate_midpoint(const Model& model, State& state, double h, std::span<const int> bodies);
void integrate_splitting4(const Model& model, State& state, double h, std::span<const int> bodies);

} // namespace tumble::physics
