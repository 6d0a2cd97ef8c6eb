#include "physics/integrator.h"

namespace tumble::physics {
namespace {

// Ordered from the teaching baseline to the most accurate; docs/integrators.md has the measured
// order, cost and conservation of each.
constexpr IntegratorInfo kIntegrators[] = {
    {Integrator::Euler, "euler", 1,
     "explicit Euler on (x, v, R, w), R re-orthonormalised: the course loop; loses energy"},
    {Integrator::EulerMomentum, "euler_momentum", 1,
     "explicit Euler on (x, P, q, L), q renormalised: L exact without torque, orientation drifts"},
    {Integrator::SymplecticEuler, "symplectic_euler", 1,
     "semi-implicit Euler, q by the exponential map, explicit gyroscopic term; gains energy"},
    {Integrator::ImplicitGyro, "implicit_gyro", 1,
     "semi-implicit Euler, backward Euler gyroscopic term (one Newton step); damps tumbling"},
    {Integrator::Rk4, "rk4", 4,
     "classic Runge-Kutta on (x, v, q, w) with the gyroscopic term, q renormalised each step"},
    {Integrator::Splitting, "splitting", 2,
     "symplectic Lie-Poisson splitting, exact rotations, half kicks: L exact, bounded energy"},
    {Integrator::Midpoint, "midpoint", 2,
     "implicit midpoint on (R, L_body), Newton 3x3: energy and L exact, phase error only"},
    {Integrator::Splitting4, "splitting4", 4,
     "fourth-order composition (Suzuki, five substeps) of splitting: L exact, bounded energy"},
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
