#pragma once
// The named integrators a scene (or --integrator) can choose. Each lives in its own file,
// integrator_<name>.cpp, which opens with the update it performs, its order, what it conserves
// and how it is known to fail.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tumble::physics {

enum class Integrator : std::uint8_t {
    Euler,
    EulerMomentum,
    SymplecticEuler,
    ImplicitGyro,
    Rk4,
    Splitting,
    Midpoint,
    Splitting4,
};

struct IntegratorInfo {
    Integrator id;
    std::string_view name;    // as written in scene files and on the command line
    int order;                // order of accuracy its theory gives on the rotation
    std::string_view summary; // one line for `tumble explain` and --help
};

std::span<const IntegratorInfo> integrators();
const IntegratorInfo& integrator_info(Integrator id);
std::optional<Integrator> integrator_from_name(std::string_view name);
std::string integrator_names(); // "a, b, c": for error messages

} // namespace tumble::physics
