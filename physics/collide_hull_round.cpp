// Round shapes (spheres, capsules) against convex polyhedra (boxes, convex meshes).
//
// A sphere is a point core grown by r, a capsule a segment core grown by r, so the contact is the
// core-to-hull distance minus r. When the core lies outside the hull the distance and its
// direction come from GJK (a box uses the exact clamp instead); when the core touches or enters
// the hull, from the separating-axis test of the core against the hull (face normals, and for a
// segment also segment x edge axes). A capsule lying flat on a face gets two points, the ends of
// its core clipped to the face, so that it rests on a line instead of rocking on one point.
#include "physics/closest_points.h"
#include "physics/collide.h"
#include "physics/gjk.h"
#include "physics/math.h"

#include <cmath>
#include <limits>

namespace tumble::physics {
namespace {

// True if the hull is an axis-aligned box centred at the origin (make_box_hull()).
bool is_box(const ConvexHull& h) {
    return h.faces.size() == 6 && h.vertices.size() == 8 && h.box_min == -h.box_max &&
           h.faces[0].normal == Vec3::UnitX();
}

// Segment core [p0, p1] (hull frame) against the face planes: the face with the largest
// separation of the core's lower end.
int deepest_face(const ConvexHull& h, const Vec3& p0, const Vec3& p1, double& separation) {
    int best = 0;
    separation = -kInf;
    for (int f = 0; f < static_cast<int>(h.faces.size()); ++f) {
        const Vec3& n = h.faces[f].normal;
        const double s = std::min(n.dot(p0), n.dot(p1)) - h.faces[f].offset;
        if (s > separation) separation = s, best = f;
    }
    return best;
}

// Clips the segment [p0, p1] to the side planes of face f (keeps the part over the face).
bool clip_to_face(const ConvexHull& h, int f, Vec3& p0, Vec3& p1) {
    const HullFace& face = h.faces[f];
    for (int j = 0; j < face.count; ++j) {
        const Vec3& v0 = h.vertices[h.face_vertices[face.first + j]];
        const Vec3& v1 = h.vertices[h.face_vertices[face.first + (j + 1) % face.count]];
        const Vec3 side = (v1 - v0).cross(face.normal);
        const double limit = side.dot(v0);
        const double d0 = side.dot(p0) - limit, d1 = side.dot(p1) - limit;
        if (d0 > 0.0 && d1 > 0.0) return false;
        if (d0 > 0.0)
            p0 += d0 / (d0 - d1) * (p1 - p0);
        else if (d1 > 0.0)
            p1 += d1 / (d1 - d0) * (p0 - p1);
    }
    return true;
}

// Capsule core on face f: up to two points, the clipped core ends (hull frame, then world).
void face_points(const ConvexHull& h, int f, Vec3 p0, Vec3 p1, double r, const ShapePose& pose,
                 double margin, Manifold& out) {
    out.count = 0;
    const HullFace& face = h.faces[f];
    out.normal = pose.rotation * face.normal;
    if (!clip_to_face(h, f, p0, p1)) return;
    const Vec3 ends[2] = {p0, p1};
    for (int k = 0; k < 2; ++k) {
        const double s = face.normal.dot(ends[k]) - face.offset - r;
        if (s > margin) continue;
        const Vec3 local = ends[k] - (r + 0.5 * s) * face.normal;
        out.points[out.count++] = {pose.position + pose.rotation * local, s,
                                   static_cast<std::uint32_t>(k)};
    }
}

// One point from core point c and hull point q (hull frame) at distance dist > 0.
void single_point(const Vec3& c, const Vec3& q, double dist, double r, const ShapePose& pose,
                  std::uint32_t id, Manifold& out) {
    const Vec3 n = (c - q) / dist;
    const double s = dist - r;
    out.normal = pose.rotation * n;
    out.points[0] = {pose.position + pose.rotation * (q + 0.5 * s * n), s, id};
    out.count = 1;
}

} // namespace

void collide_hull_sphere(const ConvexHull& h, const ShapePose& pose, const Vec3& c_world, double r,
                         double margin, Manifold& out) {
    out.count = 0;
    const Vec3 c = pose.rotation.transpose() * (c_world - pose.position);
    if (is_box(h)) {
        const Vec3 q = c.cwiseMax(h.box_min).cwiseMin(h.box_max); // closest point of the box
        const double dist = (c - q).norm();
        if (dist > 0.0) {
            if (dist - r > margin) return;
            return single_point(c, q, dist, r, pose, 0, out);
        }
    }
    double sep;
    const int f = deepest_face(h, c, c, sep);
    if (sep - r > margin) return;
    if (sep > 0.0) { // centre outside: the nearest point of the hull by GJK
        const GjkResult g = gjk_distance(std::span<const Vec3>(&c, 1), h.vertices);
        if (!g.overlap && g.distance > 0.0) {
            if (g.distance - r > margin) return;
            return single_point(c, g.point_b, g.distance, r, pose, 0, out);
        }
    }
    // Centre inside (or on) the hull: out through the face it is least deep below.
    const HullFace& face = h.faces[f];
    const double s = sep - r;
    out.normal = pose.rotation * face.normal;
    const Vec3 local = c - (r + 0.5 * s) * face.normal;
    out.points[0] = {pose.position + pose.rotation * local, s, 1};
    out.count = 1;
}

void collide_hull_capsule(const ConvexHull& h, const ShapePose& pose, const Vec3& p0_world,
                          const Vec3& p1_world, double r, double margin, Manifold& out) {
    out.count = 0;
    const Mat3 rt = pose.rotation.transpose();
    const Vec3 p0 = rt * (p0_world - pose.position), p1 = rt * (p1_world - pose.position);
    const Vec3 core[2] = {p0, p1};
    const GjkResult g = gjk_distance(core, h.vertices);
    if (!g.overlap && g.distance > 1e-9) {
        if (g.distance - r > margin) return;
        // Lying (nearly) flat on a face: two points. The face whose normal is within about 2.5
        // degrees of the contact direction, with the core within about 6 degrees of the face.
        const Vec3 n = (g.point_a - g.point_b) / g.distance;
        const Vec3 axis = (p1 - p0).normalized();
        for (int f = 0; f < static_cast<int>(h.faces.size()); ++f) {
            if (h.faces[f].normal.dot(n) > 0.999 && std::abs(h.faces[f].normal.dot(axis)) < 0.1) {
                face_points(h, f, p0, p1, r, pose, margin, out);
                if (out.count > 0) return;
                break;
            }
        }
        return single_point(g.point_a, g.point_b, g.distance, r, pose, 2, out);
    }
    // The core touches the hull: separating axes of a segment against a polytope.
    double face_sep;
    const int f = deepest_face(h, p0, p1, face_sep);
    double edge_sep = -kInf;
    int edge = -1;
    Vec3 edge_axis = Vec3::Zero();
    const Vec3 d = p1 - p0;
    for (int e = 0; e < static_cast<int>(h.edges.size()); ++e) {
        const Vec3 ev = h.vertices[h.edges[e].v1] - h.vertices[h.edges[e].v0];
        Vec3 axis = d.cross(ev);
        const double len = axis.norm();
        if (len < 1e-6 * d.norm() * ev.norm()) continue;
        axis /= len;
        double hull_hi = -kInf, hull_lo = kInf;
        for (const Vec3& v : h.vertices) {
            const double t = axis.dot(v);
            hull_hi = std::max(hull_hi, t), hull_lo = std::min(hull_lo, t);
        }
        const double lo = std::min(axis.dot(p0), axis.dot(p1));
        const double hi = std::max(axis.dot(p0), axis.dot(p1));
        const double s_plus = lo - hull_hi, s_minus = hull_lo - hi; // along +axis and -axis
        const double s = std::max(s_plus, s_minus);
        if (s > edge_sep)
            edge_sep = s, edge = e, edge_axis = s_plus >= s_minus ? axis : Vec3(-axis);
    }
    if (edge >= 0 && edge_sep > face_sep + 0.0005) {
        if (edge_sep - r > margin) return;
        Vec3 cs, ch;
        closest_on_segments(p0, p1, h.vertices[h.edges[edge].v0], h.vertices[h.edges[edge].v1], cs,
                            ch);
        const double s = edge_sep - r;
        out.normal = pose.rotation * edge_axis;
        out.points[0] = {pose.position + pose.rotation * (cs - (r + 0.5 * s) * edge_axis), s,
                         static_cast<std::uint32_t>(3 + edge)};
        out.count = 1;
        return;
    }
    if (face_sep - r > margin) return;
    face_points(h, f, p0, p1, r, pose, margin, out);
}

} // namespace tumble::physics
