#include "physics/diagnostics.h"

#include "physics/rigid_body.h"

namespace tumble::physics {

Vec3 spin_angular_momentum(const Model& m, const State& s, int i) {
    return world_inertia_times(s.q[i], m.inertia[i], s.w[i]);
}

Diagnostics diagnose_body(const Model& m, const State& s, int i) {
    Diagnostics d;
    if (!m.is_dynamic(i)) return d;
    const Vec3 p = m.mass[i] * s.v[i];
    d.angular_momentum = spin_angular_momentum(m, s, i);
    d.kinetic_linear = 0.5 * p.dot(s.v[i]);
    d.kinetic_angular = 0.5 * s.w[i].dot(d.angular_momentum);
    d.potential = -m.mass[i] * m.gravity_scale[i] * m.gravity.dot(s.x[i]);
    d.linear_momentum = p;
    return d;
}

Diagnostics diagnose(const Model& m, const State& s) {
    Diagnostics d;
    for (int i : m.dynamic_bodies) {
        const Vec3 p = m.mass[i] * s.v[i];
        const Vec3 spin = spin_angular_momentum(m, s, i);
        d.kinetic_linear += 0.5 * p.dot(s.v[i]);
        d.kinetic_angular += 0.5 * s.w[i].dot(spin);
        d.potential -= m.mass[i] * m.gravity_scale[i] * m.gravity.dot(s.x[i]);
        d.linear_momentum += p;
        d.angular_momentum += s.x[i].cross(p) + spin;
    }
    return d;
}

} // namespace tumble::physics
