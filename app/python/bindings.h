#pragma once
// The parts of the module _tumble (module.cpp), one file each.
#include <pybind11/pybind11.h>

namespace tumble::python {

void bind_errors(pybind11::module_& m);     // BadInput, RunFailed, TumbleWarning
void bind_scene(pybind11::module_& m);      // Scene, _load, scenes(), integrators()
void bind_trajectory(pybind11::module_& m); // Trajectory, _simulate
void bind_simulation(pybind11::module_& m); // Simulation
void bind_render(pybind11::module_& m);     // _render_frames, _render_output

} // namespace tumble::python
