#pragma once
// One step of the simulation pipeline, assembled from what the model contains:
//   1. integrate  the model's named integrator moves every dynamic body by h = model.dt
//   2. check      every dynamic body's state is finite, or the run stops here
// (Contacts, when a scene has shapes that can touch, will slot in before 1 as a velocity stage.)
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
    std::string quantity; // "position", "orientation", "velocity" or "angular velocity"
};

// Advances `state` by one step. Throws DivergenceError; `state` then holds the bad values.
void step(const Model& model, State& state);

// Throws DivergenceError for the first dynamic body whose state is not finite.
void check_finite(const Model& model, const State& state);

} // namespace tumble::physics
