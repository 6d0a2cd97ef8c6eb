// GJK distance. Notation: w = a - b is a point of the Minkowski difference Z = A - B, s_Z(d) =
// s_A(d) - s_B(-d) its support point in direction d. With v the closest point of the current
// simplex to the origin, the next support point w = s_Z(-v) gives the lower bound v.w / |v| on
// the distance; we stop when |v|^2 - v.w <= eps |v|^2 (the bound meets |v| to relative precision
// eps), which is exact for polytopes after finitely many steps. The closest point of a simplex is
// found in its Voronoi regions (Ericson, Real-Time Collision Detection, 5.1.5 and 5.1.6), and the
// simplex is reduced to the vertices that support it, carrying barycentric weights so that the
// closest points on A and B are the same combinations of the a's and b's.
#include "physics/gjk.h"

#include <cmath>

namespace tumble::physics {
namespace {

struct Vertex {
    Vec3 a, b, w;
};

struct Simplex {
    Vertex v[4];
    double weight[4];
    int n = 0;
};

Vec3 support(std::span<const Vec3> pts, const Vec3& d) {
    int best = 0;
    double best_dot = pts[0].dot(d);
    for (int i = 1; i < static_cast<int>(pts.size()); ++i) {
        const double t = pts[i].dot(d);
        if (t > best_dot) best_dot = t, best = i;
    }
    return pts[best];
}

void keep(Simplex& s, std::initializer_list<int> idx, std::initializer_list<double> weights) {
    Vertex tmp[4];
    double wt[4];
    int k = 0;
    auto wi = weights.begin();
    for (int i : idx) tmp[k] = s.v[i], wt[k] = *wi++, ++k;
    for (int i = 0; i < k; ++i) s.v[i] = tmp[i], s.weight[i] = wt[i];
    s.n = k;
}

void solve_segment(Simplex& s) {
    const Vec3 &a = s.v[0].w, &b = s.v[1].w;
    const Vec3 ab = b - a;
    const double t = -a.dot(ab) / ab.squaredNorm();
    if (!(t > 0.0)) return keep(s, {0}, {1.0});
    if (t >= 1.0) return keep(s, {1}, {1.0});
    keep(s, {0, 1}, {1.0 - t, t});
}

// Closest point of triangle abc to the origin p = 0 (Ericson 5.1.5).
void solve_triangle(Simplex& s) {
    const Vec3 &a = s.v[0].w, &b = s.v[1].w, &c = s.v[2].w;
    const Vec3 ab = b - a, ac = c - a, ap = -a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return keep(s, {0}, {1.0});
    const Vec3 bp = -b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return keep(s, {1}, {1.0});
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double t = d1 / (d1 - d3);
        return keep(s, {0, 1}, {1.0 - t, t});
    }
    const Vec3 cp = -c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return keep(s, {2}, {1.0});
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double t = d2 / (d2 - d6);
        return keep(s, {0, 2}, {1.0 - t, t});
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return keep(s, {1, 2}, {1.0 - t, t});
    }
    const double denom = 1.0 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    keep(s, {0, 1, 2}, {1.0 - v - w, v, w});
}

// Tetrahedron: the origin is inside (overlap) or outside some faces; the closest point lies on
// the nearest of those faces (Ericson 5.1.6). Returns false when the origin is inside.
bool solve_tetrahedron(Simplex& s) {
    static const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    Simplex best;
    double best_d2 = INFINITY;
    bool outside_any = false;
    for (const auto& f : faces) {
        const Vec3 &a = s.v[f[0]].w, &b = s.v[f[1]].w, &c = s.v[f[2]].w, &d = s.v[f[3]].w;
        const Vec3 n = (b - a).cross(c - a);
        const double sign_p = -a.dot(n), sign_d = (d - a).dot(n);
        if (sign_p * sign_d >= 0.0) continue; // origin on the same side as d: not outside
        outside_any = true;
        Simplex t;
        t.n = 3;
        t.v[0] = s.v[f[0]], t.v[1] = s.v[f[1]], t.v[2] = s.v[f[2]];
        solve_triangle(t);
        Vec3 p = Vec3::Zero();
        for (int i = 0; i < t.n; ++i) p += t.weight[i] * t.v[i].w;
        if (p.squaredNorm() < best_d2) best_d2 = p.squaredNorm(), best = t;
    }
    if (!outside_any) return false;
    s = best;
    return true;
}

} // namespace

GjkResult gjk_distance(std::span<const Vec3> a, std::span<const Vec3> b) {
    GjkResult out;
    Simplex s;
    s.v[0] = {a[0], b[0], a[0] - b[0]};
    s.weight[0] = 1.0;
    s.n = 1;
    Vec3 v = s.v[0].w;
    double prev = INFINITY;
    for (int iter = 0; iter < 64; ++iter) {
        const double vv = v.squaredNorm();
        if (vv < 1e-24) {
            out.overlap = true;
            break;
        }
        const Vec3 sa = support(a, -v), sb = support(b, v);
        const Vec3 w = sa - sb;
        if (vv - v.dot(w) <= 1e-12 * vv || vv >= prev) break; // no further progress
        prev = vv;
        s.v[s.n] = {sa, sb, w};
        s.weight[s.n] = 0.0;
        ++s.n;
        if (s.n == 2)
            solve_segment(s);
        else if (s.n == 3)
            solve_triangle(s);
        else if (!solve_tetrahedron(s)) {
            out.overlap = true;
            break;
        }
        v = Vec3::Zero();
        for (int i = 0; i < s.n; ++i) v += s.weight[i] * s.v[i].w;
    }
    if (out.overlap) return out;
    for (int i = 0; i < s.n; ++i) {
        out.point_a += s.weight[i] * s.v[i].a;
        out.point_b += s.weight[i] * s.v[i].b;
    }
    out.distance = (out.point_a - out.point_b).norm();
    return out;
}

} // namespace tumble::physics
