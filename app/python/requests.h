#pragma once
// Python's arguments as Tumble's requests: the scene argument of every call, and the keyword
// arguments of simulate(), render() and Simulation() as the command line's RunRequest and
// RenderRequest (app/run/run_request.h, app/run/render_request.h), so that each means what its
// option means and is refused with the option's message (tumble.BadInput).
#include "app/run/render_request.h"
#include "app/run/run_request.h"
#include "app/scene/scene.h"

#include <pybind11/pybind11.h>

namespace tumble::python {

// A tumble.Scene (copied), a built-in scene's name or a file's path (str or os.PathLike), or a
// dict in the scene format (docs/scene-format.md). Throws SceneError (tumble.BadInput) for a bad
// scene, pybind11::type_error for anything else. Each scene warning becomes a TumbleWarning.
app::Scene scene_argument(const pybind11::handle& argument);

// Loads the scene an argument names (not a tumble.Scene), warning as above.
app::Scene load_argument(const pybind11::handle& argument);

// {"integrator": str|None, "tolerance": float|(R, P)|str|None, "duration": float|None,
//  "dt": float|None, "error_estimate": None|bool|str|[t1, t2, ...]}
app::RunRequest run_request(const pybind11::dict& options);

// The picture and output keywords of render() (the names of RenderRequest's fields).
app::RenderRequest render_request(const pybind11::dict& options);

// Issues a tumble.TumbleWarning (set by the module at import) with `text`.
void warn(const std::string& text);
void set_warning_category(pybind11::handle category);

} // namespace tumble::python
