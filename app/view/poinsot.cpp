#include "app/view/poinsot.h"

#include "app/view/body_size.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tumble::app {
namespace {

using physics::Quat;
using physics::Vec3;

glm::vec3 to_glm(const Vec3& v) {
    return {float(v.x()), float(v.y()), float(v.z())};
}

constexpr glm::vec3 kEllipsoid{0.75f, 0.82f, 0.95f};
constexpr glm::vec3 kPlane{0.95f, 0.95f, 0.95f};
constexpr glm::vec3 kPolhode{1.0f, 0.75f, 0.2f};     // amber, as w's arrow
constexpr glm::vec3 kHerpolhode{0.3f, 0.85f, 0.95f}; // cyan, as L's

} // namespace

PoinsotGeometry poinsot_geometry(const Vec3& inertia, const Quat& q, const Vec3& w) {
    const Vec3 w_body = q.conjugate() * w;
    const Vec3 m = inertia.cwiseProduct(w_body); // I_body w_body
    const double two_t = w_body.dot(m);          // 2T = w . I w
    const Vec3 L = q * m;                        // L = R I_body R^T w
    PoinsotGeometry g;
    g.semi_axes = (two_t / inertia.array()).sqrt().matrix();
    g.normal = L.normalized();
    g.distance = two_t / L.norm();
    g.contact = w;
    return g;
}

PoinsotConstruction::PoinsotConstruction(const physics::Model& model, const physics::State& initial,
                                         int body)
    : body_(body) {
    const std::size_t b = std::size_t(body);
    const PoinsotGeometry g = poinsot_geometry(model.inertia[b], initial.q[b], initial.w[b]);
    const double size = body_size(model, body);
    const double longest = g.semi_axes.maxCoeff();
    scale_ = longest > 0.0 && std::isfinite(longest) ? 1.5 * size / longest : 1.0;
    record(model, initial);
}

void PoinsotConstruction::record(const physics::Model&, const physics::State& state) {
    const std::size_t b = std::size_t(body_);
    w_world_.push_back(state.w[b]);
    w_body_.push_back(state.q[b].conjugate() * state.w[b]);
}

void PoinsotConstruction::add(const physics::Model& model, const physics::State& state,
                              render::Polylines& lines) const {
    const std::size_t b = std::size_t(body_);
    const Quat& q = state.q[b];
    const Vec3 centre = state.x[b];
    const PoinsotGeometry g = poinsot_geometry(model.inertia[b], q, state.w[b]);
    if (!std::isfinite(g.distance)) return; // at rest: no ellipsoid
    const double s = scale_;
    const double pi = std::numbers::pi;
    // The ellipsoid: 8 meridians and 5 parallels of the unit sphere, stretched and turned.
    auto on_ellipsoid = [&](double theta, double phi) {
        const Vec3 u(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                     std::cos(theta));
        return to_glm(centre + s * (q * g.semi_axes.cwiseProduct(u)));
    };
    for (int m = 0; m < 8; ++m) {
        lines.begin(1.5f);
        for (int k = 0; k <= 32; ++k)
            lines.add(on_ellipsoid(pi * k / 32.0, 2.0 * pi * m / 8.0), glm::vec4(kEllipsoid, 0.5f));
    }
    for (int p = 1; p <= 5; ++p) {
        lines.begin(1.5f);
        for (int k = 0; k <= 48; ++k)
            lines.add(on_ellipsoid(pi * p / 6.0, 2.0 * pi * k / 48.0), glm::vec4(kEllipsoid, 0.5f));
    }
    // The invariable plane: a square grid around the foot of the centre's perpendicular.
    const Vec3 foot = centre + s * g.distance * g.normal;
    const Vec3 u = g.normal.unitOrthogonal(), v = g.normal.cross(u);
    const double half = 1.3 * s * g.semi_axes.maxCoeff();
    for (int i = -4; i <= 4; ++i) {
        const double a = half * i / 4.0;
        lines.begin(1.0f);
        lines.add(to_glm(foot + a * u - half * v), glm::vec4(kPlane, 0.3f));
        lines.add(to_glm(foot + a * u + half * v), glm::vec4(kPlane, 0.3f));
        lines.begin(1.0f);
        lines.add(to_glm(foot + a * v - half * u), glm::vec4(kPlane, 0.3f));
        lines.add(to_glm(foot + a * v + half * u), glm::vec4(kPlane, 0.3f));
    }
    // The polhode on the ellipsoid (turning with the body) and the herpolhode on the plane.
    lines.begin(2.5f);
    for (const Vec3& wb : w_body_)
        lines.add(to_glm(centre + s * (q * wb)), glm::vec4(kPolhode, 0.95f));
    lines.begin(2.5f);
    for (const Vec3& ww : w_world_)
        lines.add(to_glm(centre + s * ww), glm::vec4(kHerpolhode, 0.95f));
    // w: from the centre to the point of contact.
    lines.begin(3.0f);
    lines.add(to_glm(centre), glm::vec4(kPolhode, 1.0f));
    lines.add(to_glm(centre + s * state.w[b]), glm::vec4(kPolhode, 1.0f));
}

} // namespace tumble::app
