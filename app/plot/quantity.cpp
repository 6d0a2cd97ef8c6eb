#include "app/plot/quantity.h"

#include "physics/diagnostics.h"

namespace tumble::app::plot {
namespace {

// The body's mass-frame state rebuilt from its row (the inverse of physics::body_pose):
// q_mass = q_body (x) body_from_mass and x_com = x_body + R_body c, so that physics' own
// definitions (physics/diagnostics.h) apply to it.
physics::Diagnostics diagnose_row(const physics::Model& m, const StateRow& row) {
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
    return physics::diagnose_body(m, s, row.body);
}

std::vector<double> with_norm(const physics::Vec3& v) {
    return {v.x(), v.y(), v.z(), v.norm()};
}

} // namespace

const std::vector<Quantity>& quantities() {
    static const std::vector<Quantity> all = {
        {"energy", "total energy E = T + V", "J", true, true, true, false, {}},
        {"energy_drift", "energy drift (E(t) - E(0)) / |E(0)|", "1", true, true, true, true, {}},
        {"kinetic", "kinetic energy T", "J", true, true, true, false, {}},
        {"ke_trans", "translational kinetic energy", "J", false, true, true, false, {}},
        {"ke_rot", "rotational kinetic energy", "J", false, true, true, false, {}},
        {"potential", "potential energy V", "J", true, true, true, false, {}},
        {"momentum",
         "linear momentum P",
         "kg m/s",
         true,
         true,
         true,
         false,
         {"Px", "Py", "Pz", "|P|"}},
        {"L", "angular momentum L", "kg m^2/s", true, true, true, false, {"Lx", "Ly", "Lz", "|L|"}},
        {"w",
         "angular velocity w (world)",
         "rad/s",
         false,
         true,
         false,
         false,
         {"wx", "wy", "wz", "|w|"}},
        {"w_body",
         "angular velocity in the principal frame (Euler's w1, w2, w3)",
         "rad/s",
         false,
         true,
         true,
         false,
         {"w1", "w2", "w3"}},
    };
    return all;
}

const Quantity* find_quantity(std::string_view name) {
    for (const Quantity& q : quantities())
        if (q.name == name) return &q;
    return nullptr;
}

std::string quantity_names() {
    std::string out;
    for (const Quantity& q : quantities()) out += (out.empty() ? "" : ", ") + std::string(q.name);
    return out;
}

std::vector<double> scene_values(const Quantity& q, const DiagnosticsRow& r) {
    if (q.name == "energy" || q.name == "energy_drift") return {r.energy};
    if (q.name == "kinetic") return {r.kinetic};
    if (q.name == "potential") return {r.potential};
    if (q.name == "momentum") return with_norm(r.p);
    if (q.name == "L") return with_norm(r.l);
    return {};
}

std::vector<double> body_values(const Quantity& q, const physics::Model* m, const StateRow& r) {
    if (q.name == "w") return with_norm(r.w);
    if (q.name == "w_body") { // R_mass^T w, R_mass = R_body body_from_mass
        const physics::Quat mass_frame = r.q * m->body_from_mass[static_cast<std::size_t>(r.body)];
        const physics::Vec3 wb = mass_frame.conjugate() * r.w;
        return {wb.x(), wb.y(), wb.z()};
    }
    const physics::Diagnostics d = diagnose_row(*m, r);
    if (q.name == "energy" || q.name == "energy_drift") return {d.energy()};
    if (q.name == "kinetic") return {d.kinetic()};
    if (q.name == "ke_trans") return {d.kinetic_linear};
    if (q.name == "ke_rot") return {d.kinetic_angular};
    if (q.name == "potential") return {d.potential};
    if (q.name == "momentum") return with_norm(d.linear_momentum);
    if (q.name == "L") return with_norm(d.angular_momentum); // spin, I_w w
    return {};
}

} // namespace tumble::app::plot
