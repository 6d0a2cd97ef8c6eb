#pragma once
// One long call from Python (simulate, render, Simulation.step): the GIL released while Tumble
// works, so other Python threads run, and Ctrl-C mapped to the flag every long stage polls
// (io/interrupt.h: the pipeline between frames, the stepping loops between steps, "auto"'s pilots
// and camera.auto's pre-pass), so that KeyboardInterrupt comes within a frame or a step.
//
// Python's own SIGINT handler only sets a flag that the interpreter checks between bytecodes,
// never while C++ runs. So on the main thread (where Python delivers signals) a call swaps in
// io::InterruptGuard's host handler, which sets Tumble's flag; once the work has stopped and the
// handler is Python's again, the call raises KeyboardInterrupt itself. Calls from other threads
// keep Python's handling (they cannot be interrupted, as Python threads cannot).
#include "io/interrupt.h"

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

namespace tumble::python {

class CallScope {
  public:
    CallScope();
    ~CallScope();
    CallScope(const CallScope&) = delete;
    CallScope& operator=(const CallScope&) = delete;

    // Runs `work` with the GIL released (it must not touch Python objects).
    template <class Work>
    auto released(Work&& work) {
        pybind11::gil_scoped_release release;
        return work();
    }
    bool interrupted() const { return io::InterruptGuard::requested(); }
    // Raises KeyboardInterrupt("<what>") in Python (throws pybind11::error_already_set).
    [[noreturn]] static void raise_interrupt(const std::string& what);

  private:
    std::optional<io::InterruptGuard> guard_;
};

// Records the interpreter's main thread (at import).
void remember_main_thread();

} // namespace tumble::python
