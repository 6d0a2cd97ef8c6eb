// Whether two shapes can touch; the reasoning is in can_touch.h.
#include "physics/can_touch.h"

#include "physics/build.h"
#include "physics/math.h"
#include "physics/model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace tumble::physics {
namespace {

// What the test needs of one body, from its definition (before the first contact).
struct Flight {
    Vec3 x, u, a; // centre of mass, its velocity and constant acceleration
    double reach; // bounding radius, m
    double spin;  // bound of |w| swing over the whole flight, m/s (infinite: unbounded)
    bool plane;
    Vec3 normal; // planes: unit normal (the body's +z)
};

double spin_bound(const Model& m, const BodyDef& b, int i) {
    if (!m.is_dynamic(i) || m.swing[i] == 0.0) return 0.0;
    if (b.applied_torque != Vec3::Zero()) return kInf; // |w| grows without bound
    // A damper moves angular momentum between its bodies (damper.h): |L| of one is not conserved.
    for (const Damper& d : m.dampers)
        if (d.a == i || d.b == i) return kInf;
    // Torque-free: |L| = |I_body w_body| is conserved and |w| = |I^-1 L| <= |L| / I_min.
    const Quat q = b.orientation.normalized() * m.body_from_mass[i];
    const Vec3 l = m.inertia[i].cwiseProduct(q.conjugate() * b.angular_velocity);
    return l.norm() / m.inertia[i].minCoeff() * m.swing[i];
}

Flight flight(const Model& m, const BodyDef& b, int i) {
    Flight f;
    const Quat body_q = b.orientation.normalized();
    f.x = b.position + body_q * m.com_offset[i];
    f.u = b.velocity;
    f.a = Vec3::Zero();
    if (m.is_dynamic(i)) f.a = m.gravity_scale[i] * m.gravity + m.inv_mass[i] * m.applied_force[i];
    f.plane = m.shape[i].kind == ShapeKind::Plane;
    f.reach = f.plane ? kInf : bounding_radius(m, i);
    f.spin = spin_bound(m, b, i);
    f.normal = body_q * Vec3::UnitZ();
    return f;
}

std::string format(const char* fmt, auto... args) {
    char text[200];
    std::snprintf(text, sizeof text, fmt, args...);
    return text;
}

// Gap left at the closest approach of bodies i < j in free relative flight (negative: they can
// touch), and when. `r` receives the reason when they can touch.
double closest_gap(const Model& m, const Flight& p, const Flight& q, int i, int j, double& when,
                   TouchReport& r) {
    const Vec3 u = q.u - p.u, a = q.a - p.a;
    when = 0.0;
    if (a != Vec3::Zero()) {
        r.why = format("bodies %d and %d accelerate relative to each other (%.3g m/s^2): they may "
                       "meet",
                       i, j, a.norm());
        return -kInf;
    }
    const double margin =
        2.0 * m.contact.speculative_distance + m.dt * (u.norm() + p.spin + q.spin);
    if (!std::isfinite(margin)) {
        r.why = format(
            "bodies %d and %d: a non-round body spun up by an applied torque or a damper", i, j);
        return -kInf;
    }
    if (p.plane || q.plane) {
        const Flight& plane = p.plane ? p : q;
        const Flight& body = p.plane ? q : p;
        const double z0 = plane.normal.dot(body.x - plane.x);
        const double un = plane.normal.dot(body.u - plane.u);
        const double gap = z0 - body.reach - margin;
        if (un < 0.0)
            r.why = format("body %d approaches the plane %d at %.3g m/s", p.plane ? j : i,
                           p.plane ? i : j, -un);
        else if (gap <= 0.0)
            r.why = format("body %d starts within reach of the plane %d", p.plane ? j : i,
                           p.plane ? i : j);
        return un < 0.0 ? -kInf : gap;
    }
    const Vec3 d = q.x - p.x;
    const double uu = u.squaredNorm();
    when = uu > 0.0 ? std::max(0.0, -d.dot(u) / uu) : 0.0;
    const double gap = (d + when * u).norm() - p.reach - q.reach - margin;
    if (gap <= 0.0) r.why = format("bodies %d and %d come within reach at t = %.3g s", i, j, when);
    return gap;
}

} // namespace

double bounding_radius(const Model& m, int i) {
    const Shape& s = m.shape[i];
    switch (s.kind) {
    case ShapeKind::Sphere:
        return s.radius;
    case ShapeKind::Capsule:
        return s.half_length + s.radius;
    case ShapeKind::Plane:
        return kInf;
    case ShapeKind::Box:
    case ShapeKind::Mesh:
        return m.swing[i];
    }
    return kInf;
}

TouchReport find_touching_pair(const Model& m, const std::vector<BodyDef>& bodies) {
    TouchReport r;
    const int n = m.body_count();
    if (m.dynamic_bodies.empty() || n < 2) {
        r.why = m.dynamic_bodies.empty() ? "no dynamic body" : "a single body";
        return r;
    }
    std::vector<Flight> f(n);
    for (int i = 0; i < n; ++i) f[i] = flight(m, bodies[i], i);
    r.min_clearance = kInf;
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
            if (!m.is_dynamic(i) && !m.is_dynamic(j)) continue;
            if (++r.pairs_checked > kMaxPairTests) {
                r.can_touch = true;
                r.why = format("more than %lld pairs: not checked further", kMaxPairTests);
                return r;
            }
            double when = 0.0;
            const double gap = closest_gap(m, f[i], f[j], i, j, when, r);
            if (!(gap > 0.0)) { // also NaN from a bad definition: initial_state() rejects it
                r.can_touch = true;
                if (r.why.empty()) r.why = format("bodies %d and %d: not finite", i, j);
                r.a = i, r.b = j, r.when = when;
                return r;
            }
            r.min_clearance = std::min(r.min_clearance, gap);
        }
    }
    r.why = format("no two of %d bodies can meet: %lld pairs in free relative flight, the closest "
                   "passing %.3g m apart",
                   n, r.pairs_checked, r.min_clearance);
    return r;
}

} // namespace tumble::physics
