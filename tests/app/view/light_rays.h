#pragma once
// What stands in the light's way: a ray from a ground point towards the light, cast against one
// body's shape at its pose. Plain geometry in double precision, written for the shadow test and
// independent of the renderer's shadow map: where a body's shadow must fall follows from its
// shape, its pose and the light's direction alone.
#include "physics/shape.h"
#include "physics/state.h"
#include "render/mesh_data.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace tumble::render::test {

struct BodyShape {
    physics::Shape shape;
    glm::dmat3 rotation{1.0};       // body -> world
    glm::dvec3 position{0.0};       // body origin, world
    const MeshData* mesh = nullptr; // ShapeKind::Mesh: the drawn triangles, body frame
    double bound = 0.0;             // radius of a sphere about `position` holding the body
};

inline BodyShape body_shape(const physics::Shape& s, const physics::Pose& pose,
                            const MeshData* mesh) {
    BodyShape b{s,
                glm::mat3_cast(glm::dquat(pose.orientation.w(), pose.orientation.x(),
                                          pose.orientation.y(), pose.orientation.z())),
                {pose.position.x(), pose.position.y(), pose.position.z()},
                mesh};
    switch (s.kind) {
    case physics::ShapeKind::Sphere:
        b.bound = s.radius;
        break;
    case physics::ShapeKind::Box:
        b.bound = s.half_extents.norm();
        break;
    case physics::ShapeKind::Capsule:
        b.bound = s.radius + s.half_length;
        break;
    case physics::ShapeKind::Mesh:
        for (const Vertex& v : mesh->vertices)
            b.bound = std::max(b.bound, glm::length(glm::dvec3(v.position)));
        break;
    case physics::ShapeKind::Plane:
        b.bound = 1e30;
        break;
    }
    return b;
}

constexpr double kMiss = 1e300; // ray_entry's answer when the ray misses

// Distance from point p to the ray o + t u, t >= 0 (u unit).
inline double distance_to_ray(glm::dvec3 p, glm::dvec3 o, glm::dvec3 u) {
    const double t = std::max(0.0, glm::dot(p - o, u));
    return glm::length(o + t * u - p);
}

// Where the ray o + t u (t >= 0) enters the ball of radius r about the origin.
inline double sphere_entry(glm::dvec3 o, glm::dvec3 u, double r) {
    if (glm::dot(o, o) <= r * r) return 0.0;
    const double t = -glm::dot(o, u), d2 = glm::dot(o, o) - t * t;
    return t < 0.0 || d2 > r * r ? kMiss : t - std::sqrt(r * r - d2);
}

// Where the ray o + t u (t >= 0) enters the points within r of the segment from (0, 0, -h) to
// (0, 0, h), a capsule. The distance from o + t u to the segment is
// convex in t (the distance to a convex set along a line), so a golden-section search finds its
// least value, and on [0, that t] it only falls: bisection finds where it drops to r.
inline double capsule_entry(glm::dvec3 o, glm::dvec3 u, double r, double h) {
    const auto d = [&](double t) {
        const glm::dvec3 p = o + t * u;
        return glm::length(p - glm::dvec3(0.0, 0.0, std::clamp(p.z, -h, h)));
    };
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = 0.0, b = glm::length(o) + h + r;
    for (int i = 0; i < 100; ++i) {
        const double c = b - g * (b - a), e = a + g * (b - a);
        if (d(c) < d(e))
            b = e;
        else
            a = c;
    }
    double hi = 0.5 * (a + b), lo = 0.0;
    if (d(hi) > r) return kMiss;
    if (d(lo) <= r) return 0.0;
    for (int i = 0; i < 100; ++i) (d(0.5 * (lo + hi)) > r ? lo : hi) = 0.5 * (lo + hi);
    return hi;
}

// Slab test: the ray enters the box [-h, h] where it has entered all three slabs, if that comes
// before it leaves any of them.
inline double box_entry(glm::dvec3 o, glm::dvec3 u, glm::dvec3 h) {
    double enter = 0.0, exit = kMiss;
    for (int k = 0; k < 3; ++k) {
        if (u[k] == 0.0) {
            if (std::abs(o[k]) > h[k]) return kMiss;
            continue;
        }
        const double t1 = (-h[k] - o[k]) / u[k], t2 = (h[k] - o[k]) / u[k];
        enter = std::max(enter, std::min(t1, t2));
        exit = std::min(exit, std::max(t1, t2));
    }
    return enter <= exit ? enter : kMiss;
}

// Moller-Trumbore against every triangle: the nearest crossing ahead of the origin. (From
// inside the mesh that is where the ray leaves it; the shadow test asks from the ground.)
inline double mesh_entry(glm::dvec3 o, glm::dvec3 u, const MeshData& mesh) {
    double nearest = kMiss;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::dvec3 p0(mesh.vertices[mesh.indices[i]].position);
        const glm::dvec3 e1 = glm::dvec3(mesh.vertices[mesh.indices[i + 1]].position) - p0;
        const glm::dvec3 e2 = glm::dvec3(mesh.vertices[mesh.indices[i + 2]].position) - p0;
        const glm::dvec3 q = glm::cross(u, e2);
        const double det = glm::dot(e1, q);
        if (std::abs(det) < 1e-15) continue;
        const glm::dvec3 s = o - p0, w = glm::cross(s, e1);
        const double a = glm::dot(s, q) / det, b = glm::dot(u, w) / det;
        const double t = glm::dot(e2, w) / det;
        if (a >= 0.0 && b >= 0.0 && a + b <= 1.0 && t >= 0.0) nearest = std::min(nearest, t);
    }
    return nearest;
}

// How far along the ray from `origin` in the unit direction `u` it enters the body; kMiss if it
// never does.
inline double ray_entry(const BodyShape& b, glm::dvec3 origin, glm::dvec3 u) {
    if (distance_to_ray(b.position, origin, u) > b.bound) return kMiss;
    const glm::dmat3 to_body = glm::transpose(b.rotation);
    const glm::dvec3 o = to_body * (origin - b.position), v = to_body * u;
    switch (b.shape.kind) {
    case physics::ShapeKind::Sphere:
        return sphere_entry(o, v, b.shape.radius);
    case physics::ShapeKind::Box:
        return box_entry(
            o, v, {b.shape.half_extents.x(), b.shape.half_extents.y(), b.shape.half_extents.z()});
    case physics::ShapeKind::Capsule:
        return capsule_entry(o, v, b.shape.radius, b.shape.half_length);
    case physics::ShapeKind::Mesh:
        return mesh_entry(o, v, *b.mesh);
    case physics::ShapeKind::Plane:
        return kMiss; // the ground receives, it casts nothing
    }
    return kMiss;
}

inline bool blocks(const BodyShape& b, glm::dvec3 origin, glm::dvec3 u) {
    return ray_entry(b, origin, u) < kMiss;
}

} // namespace tumble::render::test
