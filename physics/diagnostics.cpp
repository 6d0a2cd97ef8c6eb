#include "physics/diagnostics.h"

#include "physics/rigid_body.h"

namespace tumble::physics {

Vec3 spin_angular_momentum(const Model& m, const State& s, int i) {
    return world_inertia_times(s.q[i], m.inertia[i], s.w[i]);
}

BodyDiagnostics diagnose_body(const Model& m, const State& s, int i) {
    BodyDiagnostics b;
    if (!m.is_dynamic(i)) return b;
    b.linear_momentum = m.mass[i] * s.v[i];
    b.spin = spin_angular_momentum(m, s, i);
    b.kinetic_linear = 0.5 * b.linear_momentum.dot(s.v[i]);
    b.kinetic_angular = 0.5 * s.w[i].dot(b.spin);
    b.potential = -(m.mass[i] * m.gravity_scale[i] * m.gravity.dot(s.x[i]));
    return b;
}

Diagnostics diagnose(const Model& m, const State& s) {
    Diagnostics d;
    for (int i : m.dynamic_bodies) {
        const BodyDiagnostics b = diagnose_body(m, s, i);
        d.kinetic_linear += b.kinetic_linear;
        d.kinetic_angular += b.kinetic_angular;
        d.potential += b.potential;
        d.linear_momentum += b.linear_momentum;
        d.angular_momentum += s.x[i].cross(b.linear_momentum) + b.spin;
    }
    return d;
}

} // namespace tumble::physics
