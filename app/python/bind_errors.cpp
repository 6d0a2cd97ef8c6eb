// Tumble's failures as Python exceptions, with the command line's messages (app/cli/failure.h is
// the command line's one mapping; this is Python's): io::BadInput and its subclasses (SceneError
// names file and place) -> tumble.BadInput, a ValueError; io::Interrupted (a stage stopped by
// Ctrl-C) -> KeyboardInterrupt; anything else Tumble throws (a divergence naming body and step,
// a full disk, GL or encoder failures) -> tumble.RunFailed, a RuntimeError.
#include "app/python/bindings.h"
#include "app/python/requests.h"

#include "io/bad_input.h"
#include "io/interrupt.h"

#include <exception>
#include <new>

namespace tumble::python {
namespace py = pybind11;

namespace {

PyObject* new_class(py::module_& m, const char* name, PyObject* base, const char* doc) {
    const std::string full = "tumble." + std::string(name);
    PyObject* type = PyErr_NewExceptionWithDoc(full.c_str(), doc, base, nullptr);
    if (!type) throw py::error_already_set();
    m.add_object(name, py::handle(type));
    return type;
}

} // namespace

void bind_errors(py::module_& m) {
    static PyObject* bad_input =
        new_class(m, "BadInput", PyExc_ValueError,
                  "Input Tumble cannot use: a scene (the message names its file and the JSON "
                  "path or line:column), an option (named as the command line spells it), an "
                  "output. The command line exits 2 for it.");
    static PyObject* run_failed =
        new_class(m, "RunFailed", PyExc_RuntimeError,
                  "A run that failed for another reason than its input: a body's state became "
                  "NaN or infinite (the message names the body and the step), a full disk, an "
                  "encoder or GL failure. The command line exits 1 for it.");
    set_warning_category(new_class(m, "TumbleWarning", PyExc_UserWarning,
                                   "What the command line prints as 'tumble: warning:': a scene's "
                                   "warnings, a tolerance an integrator missed."));
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const py::error_already_set&) {
            throw;
        } catch (const py::builtin_exception&) {
            throw;
        } catch (const std::bad_alloc&) {
            throw;
        } catch (const io::Interrupted& e) {
            PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
        } catch (const io::BadInput& e) {
            PyErr_SetString(bad_input, e.what());
        } catch (const std::exception& e) {
            PyErr_SetString(run_failed, e.what());
        }
    });
}

} // namespace tumble::python
