// The registry of the named integrators (integrator.h): one row per integrator.
#include "physics/integrator.h"

#include <cstddef>

namespace tumble::physics {

// The integrators' functions, one per file integrator_<name>.cpp; only their rows call them.
void integrate_euler(const Model&, State&, double, std::span<const int>);
void integrate_euler_momentum(const Model&, State&, double, std::span<const int>);
void integrate_symplectic_euler(const Model&, State&, double, std::span<const int>);
void integrate_implicit_gyro(const Model&, State&, double, std::span<const int>);
void integrate_rk4(const Model&, State&, double, std::span<const int>);
void integrate_splitting(const Model&, State&, double, std::span<const int>);
void integrate_midpoint(const Model&, State&, double, std::span<const int>);
void integrate_splitting4(const Model&, State&, double, std::span<const int>);
void integrate_exact(const Model&, State&, double, std::span<const int>);
void integrate_splitting_exact(const Model&, State&, double, std::span<const int>);
void integrate_splitting4_exact(const Model&, State&, double, std::span<const int>);

namespace {

// Ordered from the teaching baseline to the most accurate; docs/integrators.md has the measured
// order, cost and conservation of each.
constexpr IntegratorInfo kIntegrators[] = {
    {Integrator::Euler, "euler", 1, "nothing; R stays a rotation only by re-orthonormalisation",
     "explicit Euler on (x, v, R, w), R re-orthonormalised: the course loop; loses energy",
     integrate_euler, 1.5},
    {Integrator::EulerMomentum, "euler_momentum", 1, "world L exactly without torque",
     "explicit Euler on (x, P, q, L), q renormalised: L exact without torque, orientation drifts",
     integrate_euler_momentum, 0.49},
    {Integrator::SymplecticEuler, "symplectic_euler", 1, "an isotropic torque-free body exactly",
     "semi-implicit Euler, q by the exponential map, explicit gyroscopic term; gains energy",
     integrate_symplectic_euler, 1.0},
    {Integrator::ImplicitGyro, "implicit_gyro", 1,
     "energy never rises while h|w| <= I_min / (I_max - I_min)",
     "semi-implicit Euler, backward Euler gyroscopic term (one Newton step); damps tumbling",
     integrate_implicit_gyro, 1.46},
    {Integrator::Rk4, "rk4", 4, "nothing exactly (energy and L drift as O(h^4))",
     "classic Runge-Kutta on (x, v, q, w) with the gyroscopic term, q renormalised each step",
     integrate_rk4, 2.96},
    {Integrator::Splitting, "splitting", 2,
     "world L to round-off; energy error bounded, no drift (symplectic)",
     "symplectic Lie-Poisson splitting, exact rotations, half kicks: L exact, bounded energy",
     integrate_splitting, 2.47},
    {Integrator::Midpoint, "midpoint", 2, "energy and world L (every quadratic invariant)",
     "implicit midpoint on (R, L_body), Newton 3x3: energy and L exact, phase error only",
     integrate_midpoint, 2.29},
    {Integrator::Splitting4, "splitting4", 4,
     "as splitting: world L to round-off; energy error bounded, no drift",
     "fourth-order composition (Suzuki, five substeps) of splitting: L exact, bounded energy",
     integrate_splitting4, 13.2},
    // The exact free flow (free_rotation.h): no truncation error without torque.
    {Integrator::Exact, "exact", kExactOrder,
     "energy and world L to round-off; no error but round-off (no applied torques)",
     "exact torque-free motion (Euler-Jacobi) and exact flight under constant forces; refuses "
     "applied torques",
     integrate_exact, 13.2, true, true},
    {Integrator::SplittingExact, "splitting_exact", 2,
     "without torque as exact; L changes by exactly h tau per step under a torque",
     "Strang splitting: half kicks of the loads around the exact free flow (Celledoni et al. "
     "2008)",
     integrate_splitting_exact, 13.2, true, false},
    {Integrator::Splitting4Exact, "splitting4_exact", 4, "as splitting_exact",
     "fourth-order composition (Suzuki, five substeps) of splitting_exact",
     integrate_splitting4_exact, 66.2, true, false},
};

// The handles index the table: one row per enumerator, in order.
constexpr bool rows_follow_handles() {
    for (std::size_t k = 0; k < std::size(kIntegrators); ++k)
        if (kIntegrators[k].id != static_cast<Integrator>(k)) return false;
    return std::size(kIntegrators) == static_cast<std::size_t>(Integrator::Count);
}
static_assert(rows_follow_handles(), "kIntegrators needs one row per Integrator, in enum order");

} // namespace

std::span<const IntegratorInfo> integrators() {
    return kIntegrators;
}

const IntegratorInfo& integrator_info(Integrator id) {
    return kIntegrators[static_cast<std::size_t>(id)];
}

std::optional<Integrator> integrator_from_name(std::string_view name) {
    for (const IntegratorInfo& info : kIntegrators)
        if (info.name == name) return info.id;
    return std::nullopt;
}

std::string order_text(int order) {
    return order == kExactOrder ? "exact" : std::to_string(order);
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
