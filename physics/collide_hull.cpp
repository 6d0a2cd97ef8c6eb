// Convex polyhedra (boxes, convex meshes) against each other and against planes.
//
// Hull against hull is the separating-axis test (SAT) followed by clipping, as in Box2D's polygon
// collider and its 3D form by Gregorius ("The Separating Axis Test between Convex Polyhedra", GDC
// 2013). Two convex polyhedra are disjoint iff some axis separates them, and it suffices to try
//   - the face normals of A and of B: separation = (deepest point of the other hull below the
//     face plane), and
//   - the cross products eA x eB of an edge of A and an edge of B, but only for edge pairs whose
//     arcs on the Gauss map intersect (those are the faces of the Minkowski difference; the rest
//     can never be the axis of least penetration and would give false positives).
// The axis of largest separation is the contact normal; its separation is the penetration depth
// when negative. Faces are preferred unless an edge axis is better by a small tolerance, so that
// a resting box keeps a face normal instead of flickering to an edge axis that is equal up to
// round-off. For a face axis the manifold is the incident face (the face of the other hull most
// anti-parallel to the reference normal) clipped to the side planes of the reference face
// (Sutherland-Hodgman), keeping the points below the reference plane plus the margin. For an edge
// axis it is one point, midway between the closest points of the two edges.
#include "physics/closest_points.h"
#include "physics/collide.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tumble::physics {
namespace {

constexpr double kLinearSlop = 0.005;                // m, Box2D's length scale of "touching"
constexpr double kAxisTolerance = 0.1 * kLinearSlop; // prefer faces, and A's faces, within this

std::uint32_t feature_id(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    std::uint32_t h = 2166136261u; // FNV-1a over the four feature numbers
    for (std::uint32_t x : {a, b, c, d}) h = (h ^ x) * 16777619u;
    return h;
}

// A hull's vertices and face normals expressed in another body's frame: x' = R x + t.
struct Transformed {
    std::vector<Vec3> vertices, normals;
    std::vector<double> offsets;
};

void transform_hull(const ConvexHull& h, const Mat3& r, const Vec3& t, Transformed& out) {
    out.vertices.resize(h.vertices.size());
    out.normals.resize(h.faces.size());
    out.offsets.resize(h.faces.size());
    for (std::size_t i = 0; i < h.vertices.size(); ++i) out.vertices[i] = r * h.vertices[i] + t;
    for (std::size_t f = 0; f < h.faces.size(); ++f) {
        out.normals[f] = r * h.faces[f].normal;
        out.offsets[f] = h.faces[f].offset + out.normals[f].dot(t);
    }
}

struct FaceQuery {
    double separation = -std::numeric_limits<double>::infinity();
    int face = -1;
};

// Largest separation of `other` (vertices in h's frame) from the face planes of h.
FaceQuery query_faces(const ConvexHull& h, const std::vector<Vec3>& other) {
    FaceQuery q;
    for (int f = 0; f < static_cast<int>(h.faces.size()); ++f) {
        const Vec3& n = h.faces[f].normal;
        double lowest = std::numeric_limits<double>::infinity();
        for (const Vec3& v : other) lowest = std::min(lowest, n.dot(v));
        const double s = lowest - h.faces[f].offset;
        if (s > q.separation) q.separation = s, q.face = f;
    }
    return q;
}

struct EdgeQuery {
    double separation = -std::numeric_limits<double>::infinity();
    int edge_a = -1, edge_b = -1;
    Vec3 axis = Vec3::Zero();
};

// Arcs ab and cd of the Gauss map intersect (Gregorius): c and d lie on opposite sides of the
// plane of arc ab, a and b on opposite sides of the plane of arc cd, and in the same hemisphere.
bool minkowski_face(const Vec3& a, const Vec3& b, const Vec3& bxa, const Vec3& c, const Vec3& d,
                    const Vec3& dxc) {
    const double cba = c.dot(bxa), dba = d.dot(bxa), adc = a.dot(dxc), bdc = b.dot(dxc);
    return cba * dba < 0.0 && adc * bdc < 0.0 && cba * bdc > 0.0;
}

// Edge pairs, in A's frame (B given by `tb`).
EdgeQuery query_edges(const ConvexHull& ha, const ConvexHull& hb, const Transformed& tb) {
    EdgeQuery q;
    for (int i = 0; i < static_cast<int>(ha.edges.size()); ++i) {
        const HullEdge& ea = ha.edges[i];
        const Vec3 &a = ha.faces[ea.left].normal, &b = ha.faces[ea.right].normal;
        const Vec3 bxa = b.cross(a);
        const Vec3& pa = ha.vertices[ea.v0];
        const Vec3 da = ha.vertices[ea.v1] - pa;
        for (int j = 0; j < static_cast<int>(hb.edges.size()); ++j) {
            const HullEdge& eb = hb.edges[j];
            // B's normals negated: the Gauss map of the Minkowski difference A - B.
            const Vec3 c = -tb.normals[eb.left], d = -tb.normals[eb.right];
            if (!minkowski_face(a, b, bxa, c, d, d.cross(c))) continue;
            const Vec3 db = tb.vertices[eb.v1] - tb.vertices[eb.v0];
            Vec3 axis = da.cross(db);
            const double len = axis.norm();
            if (len < 1e-6 * da.norm() * db.norm())
                continue; // parallel edges: a face axis covers it
            axis /= len;
            if (axis.dot(pa - ha.centroid) < 0.0) axis = -axis; // point out of A
            const double s = axis.dot(tb.vertices[eb.v0] - pa);
            if (s > q.separation) q.separation = s, q.edge_a = i, q.edge_b = j, q.axis = axis;
        }
    }
    return q;
}

// A polygon vertex while clipping: its position, the two features that made it (an incident
// vertex: (k, 0xffff); a clip point: (the edge it lies on, the clip plane)), and the feature
// carrying the polygon edge that leaves it (an incident edge k, or 0x8000 | clip plane j).
struct ClipVertex {
    Vec3 p;
    std::uint32_t f1, f2, out;
};

// Face contact: reference face `rf` of hull `ref` (its own frame), incident hull `inc` given in
// that frame. Writes world points through `pose` (the reference hull's pose).
void face_contact(const ConvexHull& ref, int rf, const Transformed& inc, const ConvexHull& inc_hull,
                  const ShapePose& pose, bool ref_is_b, double margin, Manifold& out) {
    const HullFace& face = ref.faces[rf];
    const Vec3& n = face.normal;
    int inc_face = 0;
    double most_anti = std::numeric_limits<double>::infinity();
    for (int f = 0; f < static_cast<int>(inc.normals.size()); ++f) {
        const double d = inc.normals[f].dot(n);
        if (d < most_anti) most_anti = d, inc_face = f;
    }
    thread_local std::vector<ClipVertex> poly, next;
    poly.clear();
    const HullFace& iface = inc_hull.faces[inc_face];
    for (int k = 0; k < iface.count; ++k)
        poly.push_back({inc.vertices[inc_hull.face_vertices[iface.first + k]],
                        static_cast<std::uint32_t>(k), 0xffffu, static_cast<std::uint32_t>(k)});
    for (int j = 0; j < face.count && !poly.empty(); ++j) {
        const Vec3& v0 = ref.vertices[ref.face_vertices[face.first + j]];
        const Vec3& v1 = ref.vertices[ref.face_vertices[face.first + (j + 1) % face.count]];
        const Vec3 side = (v1 - v0).cross(n); // outward normal of the face's edge j
        const double limit = side.dot(v0);
        next.clear();
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const ClipVertex& p = poly[k];
            const ClipVertex& q = poly[(k + 1) % poly.size()];
            const double dp = side.dot(p.p) - limit, dq = side.dot(q.p) - limit;
            const std::uint32_t plane = static_cast<std::uint32_t>(j);
            if (dp <= 0.0 && dq <= 0.0) {
                next.push_back(q);
            } else if (dp <= 0.0) { // leaving: the output edge now runs along the clip plane
                next.push_back({p.p + dp / (dp - dq) * (q.p - p.p), p.out, plane, 0x8000u | plane});
            } else if (dq <= 0.0) { // entering
                next.push_back({p.p + dp / (dp - dq) * (q.p - p.p), p.out, plane, p.out});
                next.push_back(q);
            }
        }
        std::swap(poly, next);
    }
    thread_local std::vector<ContactPoint> pts; // every candidate: see collide_plane_hull
    pts.clear();
    for (const ClipVertex& c : poly) {
        const double s = n.dot(c.p) - face.offset;
        if (s > margin) continue;
        const Vec3 local = c.p - 0.5 * s * n; // midway between the incident point and the plane
        pts.push_back({pose.position + pose.rotation * local, s,
                       feature_id(ref_is_b ? 1u : 0u, static_cast<std::uint32_t>(rf),
                                  static_cast<std::uint32_t>(inc_face), (c.f1 << 16) | c.f2)});
    }
    const Vec3 normal = pose.rotation * n;
    out.normal = ref_is_b ? Vec3(-normal) : normal;
    const int count = reduce_manifold(out.normal, pts.data(), static_cast<int>(pts.size()));
    for (int i = 0; i < count; ++i) out.points[i] = pts[i];
    out.count = count;
}

} // namespace

void collide_hulls(const ConvexHull& ha, const ShapePose& pa, const ConvexHull& hb,
                   const ShapePose& pb, double margin, Manifold& out) {
    out.count = 0;
    thread_local Transformed b_in_a, a_in_b;
    const Mat3 r_ab = pa.rotation.transpose() * pb.rotation; // B's frame -> A's frame
    transform_hull(hb, r_ab, pa.rotation.transpose() * (pb.position - pa.position), b_in_a);
    transform_hull(ha, r_ab.transpose(), pb.rotation.transpose() * (pa.position - pb.position),
                   a_in_b);
    const FaceQuery fa = query_faces(ha, b_in_a.vertices);
    if (fa.separation > margin) return;
    const FaceQuery fb = query_faces(hb, a_in_b.vertices);
    if (fb.separation > margin) return;
    const EdgeQuery e = query_edges(ha, hb, b_in_a);
    if (e.separation > margin) return;

    const double best_face = std::max(fa.separation, fb.separation);
    if (e.edge_a >= 0 && e.separation > best_face + kAxisTolerance) {
        const HullEdge& ea = ha.edges[e.edge_a];
        const HullEdge& eb = hb.edges[e.edge_b];
        Vec3 ca, cb;
        closest_on_segments(ha.vertices[ea.v0], ha.vertices[ea.v1], b_in_a.vertices[eb.v0],
                            b_in_a.vertices[eb.v1], ca, cb);
        out.normal = pa.rotation * e.axis;
        out.points[0] = {pa.position + pa.rotation * (0.5 * (ca + cb)), e.separation,
                         feature_id(2u, static_cast<std::uint32_t>(e.edge_a),
                                    static_cast<std::uint32_t>(e.edge_b), 0u)};
        out.count = 1;
        return;
    }
    // B's face is the reference only when clearly better, and never when the two best faces are
    // (nearly) parallel, facing each other: then either would do, and always taking A's keeps the
    // feature ids, and so the warm start, from flipping with every tilt of a resting box.
    const bool facing = ha.faces[fa.face].normal.dot(b_in_a.normals[fb.face]) < -0.999;
    if (fb.separation > fa.separation + kAxisTolerance && !facing)
        face_contact(hb, fb.face, a_in_b, ha, pb, true, margin, out);
    else
        face_contact(ha, fa.face, b_in_a, hb, pa, false, margin, out);
}

void collide_plane_hull(const Vec3& n, double offset, const ConvexHull& hull, const ShapePose& pose,
                        double margin, Manifold& out) {
    out.count = 0;
    out.normal = n;
    const Vec3 n_local = pose.rotation.transpose() * n;
    const double base = n.dot(pose.position) - offset;
    // Every vertex within the margin is a candidate, however many: the reduction keeps the
    // deepest and those level with it. A fixed buffer of 64 once dropped the rest unseen, and a
    // spinning top whose margin (1 cm + h |w| swing, 6 cm at 300 rad/s) took in more than 64 of
    // its vertices lost its tip when the tip came late in the mesh's vertex order: the tip fell
    // through the table (3 cm deep in 1 s) while the rim rested on it.
    thread_local std::vector<ContactPoint> pts;
    pts.clear();
    for (int i = 0; i < static_cast<int>(hull.vertices.size()); ++i) {
        const double s = base + n_local.dot(hull.vertices[i]);
        if (s > margin) continue;
        const Vec3 p = pose.position + pose.rotation * hull.vertices[i] - 0.5 * s * n;
        pts.push_back({p, s, static_cast<std::uint32_t>(i)});
    }
    const int count = reduce_manifold(n, pts.data(), static_cast<int>(pts.size()));
    for (int i = 0; i < count; ++i) out.points[i] = pts[i];
    out.count = count;
}

int reduce_manifold(const Vec3& normal, ContactPoint* p, int count) {
    if (count <= 4) return count;
    // Points about level with the deepest are "touching": within kNear of it plus kFlat times
    // their distance from it across the normal (a face lying on the other within about 1 degree).
    // The rest are speculative, included only if fewer than 4 touch, least separated first. A
    // fast body's margin reaches far (a box sliding at 25 m/s keeps points 10 cm apart): without
    // this its top corners would take slots from its bottom ones. A fixed band of 1 cm failed a
    // tilted ring of vertices (a top's 1.5 mm flat tip at 15 degrees, its far side 0.8 mm up):
    // choosing by area dropped the vertices beside the deepest, the ones rolling onto the plane
    // within the step; they sank unconstrained and the next step's push-out lifted the body for
    // free (+3% energy in 4 s). Kept as the least separated points, they catch the roll.
    constexpr double kNear = 1e-4; // m
    constexpr double kFlat = 0.02; // rad
    int i0 = 0;
    for (int i = 1; i < count; ++i)
        if (p[i].separation < p[i0].separation) i0 = i;
    const ContactPoint lowest = p[i0];
    int near = 0;
    for (int i = 0; i < count; ++i) {
        const Vec3 d = p[i].point - lowest.point;
        const double across = (d - normal.dot(d) * normal).norm();
        if (p[i].separation <= lowest.separation + kNear + kFlat * across)
            std::swap(p[near++], p[i]);
    }
    if (near < 4) { // keep all touching points, then the least separated others
        std::sort(p + near, p + count, [](const ContactPoint& a, const ContactPoint& b) {
            return a.separation < b.separation;
        });
        return 4;
    }
    count = near;
    if (count == 4) return 4;
    // 1: the deepest point (first on ties).
    int i1 = 0;
    for (int i = 1; i < count; ++i)
        if (p[i].separation < p[i1].separation) i1 = i;
    // 2: the farthest from it.
    int i2 = -1;
    double best = -1.0;
    for (int i = 0; i < count; ++i) {
        const double d = (p[i].point - p[i1].point).squaredNorm();
        if (i != i1 && d > best) best = d, i2 = i;
    }
    // 3: the largest triangle with 1 and 2 (signed by the normal: either side counts).
    int i3 = -1;
    best = -1.0;
    double sign = 1.0;
    for (int i = 0; i < count; ++i) {
        if (i == i1 || i == i2) continue;
        const double a = (p[i2].point - p[i1].point).cross(p[i].point - p[i1].point).dot(normal);
        if (std::abs(a) > best) best = std::abs(a), i3 = i, sign = a < 0.0 ? -1.0 : 1.0;
    }
    // 4: the point adding the most area outside triangle 1-2-3 (across any of its edges).
    int i4 = -1;
    best = 0.0;
    const int tri[3] = {i1, i2, i3};
    for (int i = 0; i < count; ++i) {
        if (i == i1 || i == i2 || i == i3) continue;
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = p[tri[k]].point;
            const Vec3& b = p[tri[(k + 1) % 3]].point;
            const double outside = -sign * (b - a).cross(p[i].point - a).dot(normal);
            if (outside > best) best = outside, i4 = i;
        }
    }
    ContactPoint kept[4] = {p[i1], p[i2], p[i3], p[i4 >= 0 ? i4 : i3]};
    const int n = i4 >= 0 ? 4 : 3;
    for (int i = 0; i < n; ++i) p[i] = kept[i];
    return n;
}

} // namespace tumble::physics
