// The compiled half of the Python package `tumble` (python/tumble/__init__.py is the other): a
// scene -> RunPlan -> Simulation through app/run/prepare_run.h, as every command of the command
// line, so that a scene gives the same bits from Python as from `tumble`. Arrays, not objects
// (MuJoCo's way): a trajectory's states are NumPy views of flat vectors, frames one uint8 array.
#include "app/python/bindings.h"
#include "app/python/call_scope.h"
#include "render/video_sink.h"

PYBIND11_MODULE(_tumble, m) {
    namespace py = pybind11;
    using namespace tumble::python;
    m.doc() = "Tumble's compiled core; use the package `tumble` (import tumble).";
    m.attr("__version__") = TUMBLE_VERSION;
    remember_main_thread();
    tumble::render::quiet_video_logs(); // FFmpeg's info lines, as the command line's main() does
    bind_errors(m);
    bind_scene(m);
    bind_trajectory(m);
    bind_simulation(m);
    bind_render(m);
}
