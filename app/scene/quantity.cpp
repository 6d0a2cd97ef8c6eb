#include "app/scene/quantity.h"

#include "physics/diagnostics.h"

#include <cmath>

namespace tumble::app {
namespace {

constexpr QuantityInfo kCatalogue[kQuantityCount] = {
    {"energy", "total energy E = T + V", "J", 1, {}, "", true, false},
    {"energy_drift", "energy drift (E(t) - E(0)) / |E(0)|", "1", 1, {}, "", true, true},
    {"kinetic", "kinetic energy T", "J", 1, {}, "", true, false},
    {"ke_trans", "translational kinetic energy", "J", 1, {}, "", true, false},
    {"ke_rot", "rotational kinetic energy", "J", 1, {}, "", true, false},
    {"potential", "potential energy V", "J", 1, {}, "", true, false},
    {"momentum", "linear momentum P", "kg m/s", 3, {"Px", "Py", "Pz"}, "|P|", true, false},
    {"L", "angular momentum L", "kg m^2/s", 3, {"Lx", "Ly", "Lz"}, "|L|", true, false},
    {"w", "angular velocity w (world)", "rad/s", 3, {"wx", "wy", "wz"}, "|w|", false, false},
    {"w_body",
     "angular velocity in the principal frame (Euler's w1, w2, w3)",
     "rad/s",
     3,
     {"w1", "w2", "w3"},
     "",
     false,
     false},
};

physics::Diagnostics diagnostics_of(const physics::Model& m, const physics::State& s, int body) {
    return body < 0 ? physics::diagnose(m, s) : physics::diagnose_body(m, s, body);
}

std::array<double, 3> vec(const physics::Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

} // namespace

const QuantityInfo& quantity_info(Quantity q) {
    return kCatalogue[static_cast<int>(q)];
}

std::optional<Quantity> parse_quantity(std::string_view name) {
    for (int i = 0; i < kQuantityCount; ++i)
        if (name == kCatalogue[i].name) return static_cast<Quantity>(i);
    return std::nullopt;
}

std::string quantity_names() {
    std::string out;
    for (const QuantityInfo& i : kCatalogue) out += (out.empty() ? "" : ", ") + std::string(i.name);
    return out;
}

double energy_of(const physics::Model& m, const physics::State& s, int body) {
    return diagnostics_of(m, s, body).energy();
}

std::array<double, 3> quantity_value(Quantity q, const physics::Model& m, const physics::State& s,
                                     int body, double e0) {
    switch (q) {
    case Quantity::Energy:
        return {energy_of(m, s, body), 0, 0};
    case Quantity::EnergyDrift: {
        const double e = energy_of(m, s, body);
        return {e0 != 0.0 ? (e - e0) / std::abs(e0) : e - e0, 0, 0};
    }
    case Quantity::Kinetic:
        return {diagnostics_of(m, s, body).kinetic(), 0, 0};
    case Quantity::KineticTranslational:
        return {diagnostics_of(m, s, body).kinetic_linear, 0, 0};
    case Quantity::KineticRotational:
        return {diagnostics_of(m, s, body).kinetic_angular, 0, 0};
    case Quantity::Potential:
        return {diagnostics_of(m, s, body).potential, 0, 0};
    case Quantity::Momentum:
        return vec(diagnostics_of(m, s, body).linear_momentum);
    case Quantity::AngularMomentum:
        return vec(diagnostics_of(m, s, body).angular_momentum);
    case Quantity::AngularVelocity:
        return vec(s.w[std::size_t(body)]);
    case Quantity::AngularVelocityBody: // R^T w: the mass frame's axes are the principal ones
        return vec(s.q[std::size_t(body)].conjugate() * s.w[std::size_t(body)]);
    }
    return {0, 0, 0};
}

} // namespace tumble::app
