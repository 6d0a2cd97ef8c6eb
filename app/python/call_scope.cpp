#include "app/python/call_scope.h"

#include <pythread.h>

namespace tumble::python {
namespace {

unsigned long g_main_thread = 0;

} // namespace

void remember_main_thread() {
    namespace py = pybind11;
    g_main_thread =
        py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
}

CallScope::CallScope() {
    if (PyThread_get_thread_ident() == g_main_thread)
        guard_.emplace(io::InterruptGuard::Mode::host);
}

CallScope::~CallScope() = default;

void CallScope::raise_interrupt(const std::string& what) {
    PyErr_SetString(PyExc_KeyboardInterrupt, what.c_str());
    throw pybind11::error_already_set();
}

} // namespace tumble::python
