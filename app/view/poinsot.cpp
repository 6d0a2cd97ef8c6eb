#include "app/view/poinsot.h"

#include "app/scene/scene_check.h"
#include "app/view/body_size.h"
#include "app/view/to_glm.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace tumble::app {
namespace {

using physics::Quat;
using physics::Vec3;

glm::dvec3 to_d(const Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

constexpr double kPi = std::numbers::pi;
constexpr glm::vec3 kEllipsoid{0.62f, 0.78f, 1.0f};
constexpr glm::vec3 kPlane{0.92f, 0.92f, 0.96f};
constexpr glm::vec3 kPolhode{1.0f, 0.72f, 0.16f};   // amber, as w's arrow
constexpr glm::vec3 kHerpolhode{0.2f, 0.9f, 0.95f}; // cyan
constexpr glm::vec3 kWarning{1.0f, 0.35f, 0.3f};
constexpr double kPlaneReach = 1.15; // the plane's half side, in longest semi-axes

// The plane's square: its centre (the foot of the centre's perpendicular) and two unit vectors
// along it.
struct PlaneFrame {
    Vec3 foot, u, v;
    double half;
};

PlaneFrame plane_frame(const Vec3& centre, const PoinsotGeometry& g, double s) {
    const Vec3 u = g.normal.unitOrthogonal();
    return {centre + s * g.distance * g.normal, u, g.normal.cross(u),
            kPlaneReach * s * g.semi_axes.maxCoeff()};
}

void add_glass(const Vec3& centre, const Quat& q, const PoinsotGeometry& g, const PlaneFrame& p,
               double s, render::SceneView& view) {
    const glm::dquat r(q.w(), q.x(), q.y(), q.z());
    glm::dmat4 e = glm::dmat4(glm::mat3_cast(r));
    for (int k = 0; k < 3; ++k) e[k] *= s * g.semi_axes[k];
    e[3] = glm::dvec4(to_d(centre), 1.0);
    view.glass.push_back({render::MeshKind::Sphere, glm::mat4(e), glm::vec4(kEllipsoid, 0.2f)});
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(to_d(p.u) * p.half, 0.0);
    m[1] = glm::dvec4(to_d(p.v) * p.half, 0.0);
    m[2] = glm::dvec4(to_d(p.u.cross(p.v)), 0.0);
    m[3] = glm::dvec4(to_d(p.foot), 1.0);
    view.glass.push_back({render::MeshKind::Plane, glm::mat4(m), glm::vec4(kPlane, 0.2f)});
}

// The ellipsoid's three principal sections (they turn with the body: the rolling shows) and the
// plane's grid.
void add_outlines(const Vec3& centre, const Quat& q, const PoinsotGeometry& g, const PlaneFrame& p,
                  double s, render::Polylines& lines) {
    for (int i = 0; i < 3; ++i) {
        const int a = (i + 1) % 3, b = (i + 2) % 3;
        lines.begin(1.5f);
        for (int k = 0; k <= 64; ++k) {
            const double phi = 2.0 * kPi * k / 64.0;
            Vec3 local = Vec3::Zero();
            local[a] = g.semi_axes[a] * std::cos(phi);
            local[b] = g.semi_axes[b] * std::sin(phi);
            lines.add(to_glm(centre + s * (q * local)), glm::vec4(kEllipsoid, 0.6f));
        }
    }
    for (int i = -3; i <= 3; ++i) {
        const double a = p.half * i / 3.0;
        for (const auto& [along, across] : {std::pair{p.u, p.v}, std::pair{p.v, p.u}}) {
            lines.begin(1.0f);
            lines.add(to_glm(p.foot + a * along - p.half * across), glm::vec4(kPlane, 0.3f));
            lines.add(to_glm(p.foot + a * along + p.half * across), glm::vec4(kPlane, 0.3f));
        }
    }
}

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

std::string poinsot_torque(const Scene& scene, const physics::Model& model, int body) {
    const Vec3& tau = model.applied_torque[std::size_t(body)];
    if (tau != Vec3::Zero()) {
        char text[160];
        std::snprintf(text, sizeof text, "an applied torque (%g, %g, %g) N m turns it", tau.x(),
                      tau.y(), tau.z());
        return text;
    }
    if (!model.passes.contacts) return "";
    const physics::TouchReport& t = model.touch;
    if (t.a == body || t.b == body)
        return "contacts push on it where it touches \"" +
               scene.looks[std::size_t(t.a == body ? t.b : t.a)].name + "\"";
    return "contacts are on in this scene, and may push on it";
}

std::string poinsot_warning(const Scene& scene) {
    const RenderSettings::BodyRef& body = scene.render.poinsot;
    if (body.index < 0) return "";
    const CheckedStart start = build_checked(scene, scene.world.dt);
    const std::string why = poinsot_torque(scene, start.model, body.index);
    if (why.empty()) return "";
    return "Poinsot's construction assumes no torque about the centre of mass of \"" + body.name +
           "\", but " + why + ": T and L change, the plane moves and the polhode does not close";
}

PoinsotFraming poinsot_framing(const physics::Model& model, const physics::State& state, int body,
                               const glm::dvec3& hint) {
    const std::size_t b = std::size_t(body);
    const PoinsotGeometry g = poinsot_geometry(model.inertia[b], state.q[b], state.w[b]);
    PoinsotFraming f;
    const Vec3 centre = state.x[b];
    if (!std::isfinite(g.distance)) { // at rest: the body alone
        const double r = physics::bounding_radius(model, body);
        for (int k = 0; k < 8; ++k)
            f.points.push_back(to_d(centre) +
                               r * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
        f.direction = glm::length(hint) > 0.0 ? hint : glm::dvec3(1, -1, 0.5);
        f.up = glm::dvec3(0, 0, 1);
        return f;
    }
    const double s = 1.5 * body_size(model, body) / g.semi_axes.maxCoeff();
    const PlaneFrame p = plane_frame(centre, g, s);
    // The ellipsoid's extent along its axes and the rim of the plane's square.
    for (int k = 0; k < 3; ++k)
        for (double sign : {-1.0, 1.0}) {
            Vec3 local = Vec3::Zero();
            local[k] = sign * g.semi_axes[k];
            f.points.push_back(to_d(centre + s * (state.q[b] * local)));
        }
    for (int k = 0; k < 8; ++k) {
        const double a = 2.0 * kPi * k / 8.0;
        f.points.push_back(to_d(p.foot + p.half * (std::cos(a) * p.u + std::sin(a) * p.v)));
    }
    f.up = -to_d(g.normal); // from the plane towards the centre: the plane is the floor
    glm::dvec3 along = hint - glm::dot(hint, f.up) * f.up; // the hint, along the plane
    if (glm::length(along) < 1e-9 * std::max(1.0, glm::length(hint))) along = to_d(p.u);
    const double elevation = glm::radians(35.0);
    f.direction = std::sin(elevation) * f.up + std::cos(elevation) * glm::normalize(along);
    return f;
}

PoinsotConstruction::PoinsotConstruction(const Scene& scene, const physics::Model& model,
                                         const physics::State& initial, int body)
    : body_(body), torque_(poinsot_torque(scene, model, body)) {
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
                              render::SceneView& view) const {
    const std::size_t b = std::size_t(body_);
    const Quat& q = state.q[b];
    const Vec3 centre = state.x[b];
    const PoinsotGeometry g = poinsot_geometry(model.inertia[b], q, state.w[b]);
    if (!std::isfinite(g.distance)) return; // at rest: no ellipsoid
    const double s = scale_;
    const PlaneFrame p = plane_frame(centre, g, s);
    add_glass(centre, q, g, p, s, view);
    render::Polylines& lines = view.lines;
    add_outlines(centre, q, g, p, s, lines);
    // The polhode on the ellipsoid (turning with the body) and the herpolhode on the plane.
    lines.begin(3.0f);
    for (const Vec3& wb : w_body_)
        lines.add(to_glm(centre + s * (q * wb)), glm::vec4(kPolhode, 1.0f));
    lines.begin(3.0f);
    for (const Vec3& ww : w_world_)
        lines.add(to_glm(centre + s * ww), glm::vec4(kHerpolhode, 1.0f));
    // w: from the centre to the point of contact, and the point itself.
    lines.begin(3.0f);
    lines.add(to_glm(centre), glm::vec4(kPolhode, 1.0f));
    lines.add(to_glm(centre + s * state.w[b]), glm::vec4(kPolhode, 1.0f));
}

std::vector<LegendItem> PoinsotConstruction::legend(bool compact) const {
    std::vector<LegendItem> items = {
        {glm::vec4(kPolhode, 1.0f), compact ? "polhode" : "polhode: path of w in the body"},
        {glm::vec4(kHerpolhode, 1.0f), compact ? "herpolhode" : "herpolhode: path of w in space"},
        {glm::vec4(kEllipsoid, 1.0f), compact ? "ellipsoid" : "energy ellipsoid (body)"},
        {glm::vec4(kPlane, 1.0f), compact ? "plane" : "invariable plane, normal L"}};
    if (!torque_.empty())
        items.push_back({glm::vec4(kWarning, 1.0f),
                         compact ? "torque: not valid" : "under torque: not Poinsot's motion"});
    return items;
}

} // namespace tumble::app
