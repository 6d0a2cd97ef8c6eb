#pragma once
// One step of the simulation pipeline, assembled from what the model contains (step.cpp tells
// the whole story):
//   1. contacts   only when two shapes can touch: find, wake, prepare, impacts, substeps of
//                 (predict, solve, integrate, relax) around the named integrator, store, sleep
//                 (contact_stage.h)
//      integrate  otherwise the model's named integrator moves every dynamic body by h = dt
//   2. check      every dynamic body's state and kinetic energy are finite, or the run stops
#include "physics/contact_stage.h"
#include "physics/model.h"
#include "physics/state.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace tumble::physics {

// A state became NaN or infinite. Never repaired silently: the run stops, naming body and step.
struct DivergenceError : std::runtime_error {
    DivergenceError(int body, std::int64_t step, std::string quantity, const std::string& what)
        : std::runtime_error(what), body(body), step(step), quantity(std::move(quantity)) {}
    int body;
    std::int64_t step;
    std::string quantity; // "position", "orientation", "velocity", "angular velocity", or a term
                          // of the kinetic energy ("kinetic energy m |v|^2", "rotational ...")
};

// Advances `state` by one step. Throws DivergenceError; `state` then holds the bad values.
void step(const Model& model, State& state);

// Scratch for step(): the contact stage's buffers and its worker threads (`threads` >= 1, the
// caller being one of them). step(model, state) uses one single-threaded workspace per calling
// thread. Results never depend on the workspace or on the thread count.
struct StepWorkspace {
    explicit StepWorkspace(int threads = 1);
    ContactStage contacts;
    ThreadPool pool;
};
void step(const Model& model, State& state, StepWorkspace& workspace);

// Throws DivergenceError for the first dynamic body whose state, or a term of whose kinetic
// energy (m |v|^2, I_max |w|^2), is not finite.
void check_finite(const Model& model, const State& state);

} // namespace tumble::physics
