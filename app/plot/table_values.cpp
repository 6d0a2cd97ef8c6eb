#include "app/plot/table_values.h"

#include "physics/diagnostics.h"

namespace tumble::app::plot {
namespace {

// The body's mass-frame state rebuilt from its row (the inverse of physics::body_pose):
// q_mass = q_body (x) body_from_mass and x_com = x_body + R_body c, so that physics' own
// definitions (physics/diagnostics.h) apply to it.
physics::State mass_frame_state(const physics::Model& m, const StateRow& row) {
    physics::State s;
    const std::size_t n = static_cast<std::size_t>(m.body_count());
    s.x.assign(n, physics::Vec3::Zero());
    s.q.assign(n, physics::Quat::Identity());
    s.v.assign(n, physics::Vec3::Zero());
    s.w.assign(n, physics::Vec3::Zero());
    const std::size_t i = static_cast<std::size_t>(row.body);
    s.q[i] = row.q * m.body_from_mass[i];
    s.x[i] = row.x + row.q * m.com_offset[i];
    s.v[i] = row.v;
    s.w[i] = row.w;
    return s;
}

// The components, then the length when the catalogue names one.
std::vector<double> drawn(Quantity q, const std::array<double, 3>& v) {
    const QuantityInfo& info = quantity_info(q);
    std::vector<double> out(v.begin(), v.begin() + info.components);
    if (!info.norm_name.empty()) out.push_back(physics::Vec3(v[0], v[1], v[2]).norm());
    return out;
}

std::array<double, 3> vec(const physics::Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

} // namespace

bool in_diagnostics_table(Quantity q) {
    return quantity_info(q).of_scene && q != Quantity::KineticTranslational &&
           q != Quantity::KineticRotational;
}

bool needs_scene(Quantity q) {
    return q != Quantity::AngularVelocity;
}

std::vector<std::string_view> series_names(Quantity q) {
    const QuantityInfo& info = quantity_info(q);
    if (info.components == 1) return {""};
    std::vector<std::string_view> out(info.component_names.begin(),
                                      info.component_names.begin() + info.components);
    if (!info.norm_name.empty()) out.push_back(info.norm_name);
    return out;
}

std::vector<double> scene_values(Quantity q, const DiagnosticsRow& r) {
    switch (q) {
    case Quantity::Energy:
    case Quantity::EnergyDrift: // made relative to the first row by the series
        return {r.energy};
    case Quantity::Kinetic:
        return {r.kinetic};
    case Quantity::Potential:
        return {r.potential};
    case Quantity::Momentum:
        return drawn(q, vec(r.p));
    case Quantity::AngularMomentum:
        return drawn(q, vec(r.l));
    default:
        return {};
    }
}

std::vector<double> body_values(Quantity q, const physics::Model* m, const StateRow& r) {
    if (q == Quantity::AngularVelocity) return drawn(q, vec(r.w));
    const physics::State s = mass_frame_state(*m, r);
    // Energy, not drift: the series makes it relative to the first row (e0 unused here).
    const Quantity value_of = q == Quantity::EnergyDrift ? Quantity::Energy : q;
    return drawn(q, quantity_value(value_of, *m, s, r.body, 0.0));
}

} // namespace tumble::app::plot
