// Narrow-phase dispatch: orders the two shapes so that each pair family has one function, and
// flips the normal back when the order was swapped.
#include "physics/collide.h"

#include <limits>
#include <utility>

namespace tumble::physics {
namespace {

// Family order: plane < hull (box, mesh) < capsule < sphere; a pair function takes the lower
// family first.
int family(ShapeKind k) {
    switch (k) {
    case ShapeKind::Plane:
        return 0;
    case ShapeKind::Box:
    case ShapeKind::Mesh:
        return 1;
    case ShapeKind::Capsule:
        return 2;
    case ShapeKind::Sphere:
        return 3;
    }
    return 3;
}

// Capsule core ends in the world.
void capsule_core(const Shape& s, const ShapePose& p, Vec3& p0, Vec3& p1) {
    const Vec3 half = s.half_length * p.rotation.col(2);
    p0 = p.position - half;
    p1 = p.position + half;
}

void collide_ordered(const Model& m, int a, const ShapePose& pa, int b, const ShapePose& pb,
                     double margin, Manifold& out) {
    const Shape& sa = m.shape[a];
    const Shape& sb = m.shape[b];
    out.count = 0;
    switch (family(sa.kind)) {
    case 0: { // plane A: normal = body z axis, through the body origin
        const Vec3 n = pa.rotation.col(2);
        const double offset = n.dot(pa.position);
        switch (family(sb.kind)) {
        case 0:
            return; // two planes: both static
        case 1:
            return collide_plane_hull(n, offset, m.hulls[m.hull[b]], pb, margin, out);
        case 2: {
            Vec3 p0, p1;
            capsule_core(sb, pb, p0, p1);
            return collide_plane_capsule(n, offset, p0, p1, sb.radius, margin, out);
        }
        default:
            return collide_plane_sphere(n, offset, pb.position, sb.radius, margin, out);
        }
    }
    case 1: {
        const ConvexHull& ha = m.hulls[m.hull[a]];
        switch (family(sb.kind)) {
        case 1:
            return collide_hulls(ha, pa, m.hulls[m.hull[b]], pb, margin, out);
        case 2: {
            Vec3 p0, p1;
            capsule_core(sb, pb, p0, p1);
            return collide_hull_capsule(ha, pa, p0, p1, sb.radius, margin, out);
        }
        default:
            return collide_hull_sphere(ha, pa, pb.position, sb.radius, margin, out);
        }
    }
    case 2: {
        Vec3 a0, a1;
        capsule_core(sa, pa, a0, a1);
        if (family(sb.kind) == 2) {
            Vec3 b0, b1;
            capsule_core(sb, pb, b0, b1);
            return collide_capsules(a0, a1, sa.radius, b0, b1, sb.radius, margin, out);
        }
        return collide_capsule_sphere(a0, a1, sa.radius, pb.position, sb.radius, margin, out);
    }
    default:
        return collide_spheres(pa.position, sa.radius, pb.position, sb.radius, margin, out);
    }
}

} // namespace

ShapePose shape_pose(const Model& m, const Vec3& x, const Quat& q, int i) {
    // R_body = R_mass * body_from_mass^-1; body origin = x - R_body c (state.h, body_pose()).
    const Quat body = q * m.body_from_mass[i].conjugate();
    ShapePose p;
    p.rotation = body.toRotationMatrix();
    p.position = x - p.rotation * m.com_offset[i];
    return p;
}

void collide(const Model& m, int a, const ShapePose& pa, int b, const ShapePose& pb, double margin,
             Manifold& out) {
    if (family(m.shape[a].kind) <= family(m.shape[b].kind)) {
        collide_ordered(m, a, pa, b, pb, margin, out);
        return;
    }
    collide_ordered(m, b, pb, a, pa, margin, out);
    out.normal = -out.normal;
}

Aabb shape_aabb(const Model& m, int i, const ShapePose& p) {
    const Shape& s = m.shape[i];
    switch (s.kind) {
    case ShapeKind::Sphere:
        return {p.position.array() - s.radius, p.position.array() + s.radius};
    case ShapeKind::Capsule: {
        const Vec3 half = (s.half_length * p.rotation.col(2)).cwiseAbs();
        return {p.position - half - Vec3::Constant(s.radius),
                p.position + half + Vec3::Constant(s.radius)};
    }
    case ShapeKind::Box:
    case ShapeKind::Mesh: {
        // The local box [lo, hi] rotated: centre R c + p, half extents |R| e.
        const ConvexHull& h = m.hulls[m.hull[i]];
        const Vec3 c = p.position + p.rotation * (0.5 * (h.box_min + h.box_max));
        const Vec3 e = p.rotation.cwiseAbs() * (0.5 * (h.box_max - h.box_min));
        return {c - e, c + e};
    }
    case ShapeKind::Plane:
        break;
    }
    const double inf = std::numeric_limits<double>::infinity();
    return {Vec3::Constant(-inf), Vec3::Constant(inf)};
}

double shape_thickness(const Model& m, int i) {
    const Shape& s = m.shape[i];
    switch (s.kind) {
    case ShapeKind::Sphere:
    case ShapeKind::Capsule:
        return s.radius;
    case ShapeKind::Box:
        return s.half_extents.minCoeff();
    case ShapeKind::Mesh: {
        const ConvexHull& h = m.hulls[m.hull[i]];
        return 0.5 * (h.box_max - h.box_min).minCoeff();
    }
    case ShapeKind::Plane:
        break;
    }
    return std::numeric_limits<double>::infinity();
}

double plane_clearance(const Model& m, int i, const ShapePose& p, const Vec3& n, double offset) {
    const Shape& s = m.shape[i];
    const double centre = n.dot(p.position) - offset;
    switch (s.kind) {
    case ShapeKind::Sphere:
        return centre - s.radius;
    case ShapeKind::Capsule:
        return centre - std::abs(n.dot(p.rotation.col(2))) * s.half_length - s.radius;
    case ShapeKind::Box: {
        const Vec3 nl = p.rotation.transpose() * n;
        return centre - nl.cwiseAbs().dot(s.half_extents);
    }
    case ShapeKind::Mesh: {
        const Vec3 nl = p.rotation.transpose() * n;
        double lowest = std::numeric_limits<double>::infinity();
        for (const Vec3& v : m.hulls[m.hull[i]].vertices) lowest = std::min(lowest, nl.dot(v));
        return centre + lowest;
    }
    case ShapeKind::Plane:
        return -std::numeric_limits<double>::infinity();
    }
    return 0.0;
}

} // namespace tumble::physics
