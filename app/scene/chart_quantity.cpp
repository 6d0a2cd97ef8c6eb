#include "app/scene/chart_quantity.h"

#include "physics/diagnostics.h"

#include <cmath>

namespace tumble::app {
namespace {

constexpr ChartQuantityInfo kInfo[] = {
    {"energy", "J", 1, false}, {"energy_drift", "", 1, false},   {"ke_trans", "J", 1, false},
    {"ke_rot", "J", 1, false}, {"momentum", "kg m/s", 3, false}, {"L", "kg m^2/s", 3, false},
    {"w", "rad/s", 3, true},   {"w_body", "rad/s", 3, true},
};

physics::Diagnostics diagnostics_of(const physics::Model& m, const physics::State& s, int body) {
    return body < 0 ? physics::diagnose(m, s) : physics::diagnose_body(m, s, body);
}

std::array<double, 3> vec(const physics::Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

} // namespace

const ChartQuantityInfo& chart_quantity_info(ChartQuantity q) {
    return kInfo[static_cast<int>(q)];
}

std::optional<ChartQuantity> parse_chart_quantity(std::string_view name) {
    for (int i = 0; i < int(std::size(kInfo)); ++i)
        if (name == kInfo[i].name) return static_cast<ChartQuantity>(i);
    return std::nullopt;
}

std::string chart_quantity_names() {
    std::string out;
    for (const ChartQuantityInfo& i : kInfo) out += (out.empty() ? "" : ", ") + std::string(i.name);
    return out;
}

double chart_energy(const physics::Model& m, const physics::State& s, int body) {
    return diagnostics_of(m, s, body).energy();
}

std::array<double, 3> measure(ChartQuantity q, const physics::Model& m, const physics::State& s,
                              int body, double e0) {
    switch (q) {
    case ChartQuantity::Energy:
        return {chart_energy(m, s, body), 0, 0};
    case ChartQuantity::EnergyDrift: {
        const double e = chart_energy(m, s, body);
        return {e0 != 0.0 ? (e - e0) / std::abs(e0) : e - e0, 0, 0};
    }
    case ChartQuantity::KineticTranslational:
        return {diagnostics_of(m, s, body).kinetic_linear, 0, 0};
    case ChartQuantity::KineticRotational:
        return {diagnostics_of(m, s, body).kinetic_angular, 0, 0};
    case ChartQuantity::Momentum:
        return vec(diagnostics_of(m, s, body).linear_momentum);
    case ChartQuantity::AngularMomentum:
        return vec(diagnostics_of(m, s, body).angular_momentum);
    case ChartQuantity::AngularVelocity:
        return vec(s.w[std::size_t(body)]);
    case ChartQuantity::AngularVelocityBody: // R^T w: the mass frame's axes are the principal ones
        return vec(s.q[std::size_t(body)].conjugate() * s.w[std::size_t(body)]);
    }
    return {0, 0, 0};
}

} // namespace tumble::app
