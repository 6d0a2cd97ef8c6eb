// Contacts of round shapes: spheres and capsules against each other and against planes. A
// capsule is the set of points within r of its core segment, so every test here is a closest-
// point problem on points and segments (Ericson, Real-Time Collision Detection, 5.1.2 and 5.1.9),
// followed by "sphere against sphere" at the closest points.
#include "physics/collide.h"

#include "physics/closest_points.h"

#include <algorithm>
#include <cmath>

namespace tumble::physics {
namespace {

void add_point(Manifold& out, const Vec3& point, double separation, std::uint32_t id) {
    out.points[out.count++] = {point, separation, id};
}

} // namespace

void collide_spheres(const Vec3& ca, double ra, const Vec3& cb, double rb, double margin,
                     Manifold& out) {
    out.count = 0;
    const Vec3 d = cb - ca;
    const double dist2 = d.squaredNorm();
    const double reach = ra + rb + margin;
    if (dist2 > reach * reach) return;
    const double dist = std::sqrt(dist2);
    // Concentric spheres have no preferred direction: push apart along +z, deterministically.
    out.normal = dist > 1e-12 ? Vec3(d / dist) : Vec3(Vec3::UnitZ());
    const double s = dist - ra - rb;
    // Midway between the surface points ca + ra n and cb - rb n.
    add_point(out, ca + (ra + 0.5 * s) * out.normal, s, 0);
}

void collide_plane_sphere(const Vec3& n, double offset, const Vec3& c, double r, double margin,
                          Manifold& out) {
    out.count = 0;
    const double s = n.dot(c) - offset - r;
    if (s > margin) return;
    out.normal = n;
    add_point(out, c - (r + 0.5 * s) * n, s, 0);
}

void collide_capsule_sphere(const Vec3& p0, const Vec3& p1, double ra, const Vec3& c, double rb,
                            double margin, Manifold& out) {
    collide_spheres(closest_on_segment(p0, p1, c), ra, c, rb, margin, out);
}

void collide_capsules(const Vec3& a0, const Vec3& a1, double ra, const Vec3& b0, const Vec3& b1,
                      double rb, double margin, Manifold& out) {
    out.count = 0;
    const Vec3 da = a1 - a0, db = b1 - b0, r = a0 - b0;
    const double aa = da.squaredNorm(), bb = db.squaredNorm(), ab = da.dot(db);
    const double ar = da.dot(r);
    const double cross2 = aa * bb - ab * ab; // |da x db|^2
    const double reach = ra + rb + margin;

    // Nearly parallel cores (within about 0.6 degrees): lying side by side they touch along a
    // line, so take the two ends of the overlap of B's projection onto A. One closest point would
    // let the pair rock about it.
    if (cross2 <= 1e-4 * aa * bb) {
        double t0 = -ar / aa, t1 = (db.dot(da) - ar) / aa; // b0, b1 projected on a0 + t da
        if (t0 > t1) std::swap(t0, t1);
        const double lo = std::max(0.0, t0), hi = std::min(1.0, t1);
        if (hi - lo > 1e-6) {
            const Vec3 pa_lo = a0 + lo * da, pa_hi = a0 + hi * da;
            const Vec3 mid = closest_on_segment(b0, b1, 0.5 * (pa_lo + pa_hi));
            Vec3 n = mid - 0.5 * (pa_lo + pa_hi);
            n -= n.dot(da) / aa * da; // perpendicular to the cores
            const double len = n.norm();
            if (len > 1e-12) {
                n /= len;
                const double s_lo = n.dot(closest_on_segment(b0, b1, pa_lo) - pa_lo) - ra - rb;
                const double s_hi = n.dot(closest_on_segment(b0, b1, pa_hi) - pa_hi) - ra - rb;
                if (std::min(s_lo, s_hi) > margin) return;
                out.normal = n;
                if (s_lo <= margin) add_point(out, pa_lo + (ra + 0.5 * s_lo) * n, s_lo, 0);
                if (s_hi <= margin) add_point(out, pa_hi + (ra + 0.5 * s_hi) * n, s_hi, 1);
                return;
            }
        }
    }
    // General position: the closest points of the two segments.
    Vec3 pa, pb;
    closest_on_segments(a0, a1, b0, b1, pa, pb);
    if ((pb - pa).squaredNorm() > reach * reach) return;
    collide_spheres(pa, ra, pb, rb, margin, out);
    if (out.count) out.points[0].id = 2;
}

void collide_plane_capsule(const Vec3& n, double offset, const Vec3& p0, const Vec3& p1, double r,
                           double margin, Manifold& out) {
    out.count = 0;
    out.normal = n;
    const double s0 = n.dot(p0) - offset - r, s1 = n.dot(p1) - offset - r;
    if (s0 <= margin) add_point(out, p0 - (r + 0.5 * s0) * n, s0, 0);
    if (s1 <= margin) add_point(out, p1 - (r + 0.5 * s1) * n, s1, 1);
}

} // namespace tumble::physics
