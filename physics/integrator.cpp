#include "physics/integrator.h"

namespace tumble::physics {
namespace {

constexpr IntegratorInfo kIntegrators[] = {
    {Integrator::Rk4, "rk4", 4,
     "classic Runge-Kutta on (x, v, q, w) with the gyroscopic term, q renormalised each step"},
};

} // namespace

std::span<const IntegratorInfo> integrators() {
    return kIntegrators;
}

const IntegratorInfo& integrator_info(Integrator id) {
    for (const IntegratorInfo& info : kIntegrators)
        if (info.id == id) return info;
    return kIntegrators[0]; // unreachable: every enumerator has a row
}

std::optional<Integrator> integrator_from_name(std::string_view name) {
    for (const IntegratorInfo& info : kIntegrators)
        if (info.name == name) return info.id;
    return std::nullopt;
}

std::string integrator_names() {
    std::string out;
    for (const IntegratorInfo& info : kIntegrators) {
        if (!out.empty()) out += ", ";
        out += info.name;
    }
    return out;
}

} // namespace tumble::physics
