#pragma once
// Giving up a long physics loop on request. Physics knows no signals; a caller that does (the
// app's Ctrl-C, app/run/interrupt.h) passes a StopCheck, which loops that can run for long (the
// pilot runs of accuracy_plan.h over a whole duration) poll every kStopPollSteps steps, throwing
// Stopped when it answers true. An empty StopCheck never stops.
#include <cstdint>
#include <functional>
#include <stdexcept>

namespace tumble::physics {

using StopCheck = std::function<bool()>;

// Polled every 256 steps: a step of the largest scenes takes ~1 ms, so well under a second.
inline constexpr std::int64_t kStopPollSteps = 256;

struct Stopped : std::runtime_error {
    Stopped() : std::runtime_error("stopped on request") {}
};

// Throws Stopped when step `k` is a polling step and `stop` asks to stop.
inline void poll_stop(const StopCheck& stop, std::int64_t k) {
    if (stop && k % kStopPollSteps == 0 && stop()) throw Stopped();
}

} // namespace tumble::physics
