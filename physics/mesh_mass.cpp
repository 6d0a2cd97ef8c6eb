// Mass properties of a closed triangle mesh by the divergence theorem (Mirtich 1996; Eberly 2002).
//
// Every volume integral we need is of a polynomial f(x, y, z) of degree <= 2 over the solid V.
// Gauss: integral_V div F dV = sum over faces of integral_face F . n dA. Pick F with a single
// component, e.g. F = (x^2 / 2, 0, 0) for f = x, so that on a triangle only the x-component of its
// area-weighted normal d = (p1 - p0) x (p2 - p0) enters. Parametrising the triangle as
// p(u, v) = p0 + u (p1 - p0) + v (p2 - p0) turns each face integral into a polynomial integral
// over the unit triangle, which has closed forms in the vertex coordinates:
//   integral over the unit triangle of w(u, v)^k du dv, w linear with corner values w0, w1, w2,
//   = f_k(w0, w1, w2) / ((k + 1)(k + 2)) with the symmetric sums
//   f1 = w0 + w1 + w2,  f2 = w0^2 + w1^2 + w2^2 + w0 w1 + w0 w2 + w1 w2,
//   f3 = w0^3 + ... (all 10 monomials of degree 3).
// With these (and g_i = f2 + w_i (f1 + w_i), which integrates w^2 against a second coordinate):
//   6 V            = sum d.x f1(x)
//   24 int x dV    = sum d.x f2(x)       (likewise y, z)
//   60 int x^2 dV  = sum d.x f3(x)       (likewise y, z)
//   120 int xy dV  = sum d.x (y0 g0(x) + y1 g1(x) + y2 g2(x))   (likewise yz, zx)
// Then centroid c = int p dV / V and the inertia about c (unit density):
//   Ixx = int (y^2 + z^2) dV - V (cy^2 + cz^2),  Ixy = -(int xy dV - V cx cy), ...
// Exact up to round-off for any closed polyhedron, convex or not.
#include "physics/mesh.h"

#include <algorithm>
#include <map>

namespace tumble::physics {
namespace {

struct Sums {
    double f1, f2, f3, g0, g1, g2;
};

// The symmetric sums for one coordinate with corner values w0, w1, w2 (Horner-style, as Eberly).
Sums sums(double w0, double w1, double w2) {
    const double t0 = w0 + w1;
    const double t1 = w0 * w0;
    const double t2 = t1 + w1 * t0;
    Sums s;
    s.f1 = t0 + w2;
    s.f2 = t2 + w2 * s.f1;
    s.f3 = w0 * t1 + w1 * t2 + w2 * s.f2;
    s.g0 = s.f2 + w0 * (s.f1 + w0);
    s.g1 = s.f2 + w1 * (s.f1 + w1);
    s.g2 = s.f2 + w2 * (s.f1 + w2);
    return s;
}

} // namespace

MeshMassProperties mesh_mass_properties(const TriangleMesh& mesh) {
    // i[0] = 6 V; i[1..3] = 24 int (x, y, z); i[4..6] = 60 int (x^2, y^2, z^2);
    // i[7..9] = 120 int (xy, yz, zx).
    double i[10] = {};
    for (const auto& t : mesh.triangles) {
        const Vec3 &p0 = mesh.vertices[t[0]], &p1 = mesh.vertices[t[1]], &p2 = mesh.vertices[t[2]];
        const Vec3 d = (p1 - p0).cross(p2 - p0);
        const Sums x = sums(p0.x(), p1.x(), p2.x());
        const Sums y = sums(p0.y(), p1.y(), p2.y());
        const Sums z = sums(p0.z(), p1.z(), p2.z());
        i[0] += d.x() * x.f1;
        i[1] += d.x() * x.f2;
        i[2] += d.y() * y.f2;
        i[3] += d.z() * z.f2;
        i[4] += d.x() * x.f3;
        i[5] += d.y() * y.f3;
        i[6] += d.z() * z.f3;
        i[7] += d.x() * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
        i[8] += d.y() * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
        i[9] += d.z() * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
    }
    const double volume = i[0] / 6.0;
    const Vec3 first(i[1] / 24.0, i[2] / 24.0, i[3] / 24.0);
    const Vec3 second(i[4] / 60.0, i[5] / 60.0, i[6] / 60.0); // int x^2, y^2, z^2
    const double xy = i[7] / 120.0, yz = i[8] / 120.0, zx = i[9] / 120.0;

    MeshMassProperties p;
    p.volume = volume;
    if (volume <= 0.0) return p;
    const Vec3 c = first / volume;
    p.centroid = c;
    Mat3& I = p.inertia;
    I(0, 0) = second.y() + second.z() - volume * (c.y() * c.y() + c.z() * c.z());
    I(1, 1) = second.z() + second.x() - volume * (c.z() * c.z() + c.x() * c.x());
    I(2, 2) = second.x() + second.y() - volume * (c.x() * c.x() + c.y() * c.y());
    I(0, 1) = I(1, 0) = -(xy - volume * c.x() * c.y());
    I(1, 2) = I(2, 1) = -(yz - volume * c.y() * c.z());
    I(0, 2) = I(2, 0) = -(zx - volume * c.z() * c.x());
    return p;
}

std::optional<std::string> check_closed_mesh(const TriangleMesh& mesh) {
    const int nv = static_cast<int>(mesh.vertices.size());
    if (nv < 4 || mesh.triangles.size() < 4)
        return "a closed mesh needs at least 4 vertices and 4 triangles, got " +
               std::to_string(nv) + " and " + std::to_string(mesh.triangles.size());
    for (const Vec3& v : mesh.vertices)
        if (!v.allFinite()) return std::string("mesh has a non-finite vertex coordinate");
    // Directed edge -> how many triangles traverse it. Closed and consistently wound: every
    // directed edge (a, b) appears exactly once, and so does its reverse (b, a).
    std::map<std::pair<int, int>, int> directed;
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto& t = mesh.triangles[k];
        for (int j = 0; j < 3; ++j)
            if (t[j] < 0 || t[j] >= nv)
                return "triangle " + std::to_string(k) + " has a vertex index out of range";
        const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                           .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        if (!(n.norm() > 0.0)) return "triangle " + std::to_string(k) + " has zero area";
        for (int j = 0; j < 3; ++j) ++directed[{t[j], t[(j + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1)
            return "mesh is not closed and consistently wound: edge between vertices " +
                   std::to_string(edge.first) + " and " + std::to_string(edge.second) +
                   " is not shared by exactly two triangles traversing it in opposite directions";
    }
    const double volume = mesh_mass_properties(mesh).volume;
    if (!(volume > 0.0))
        return "mesh encloses no positive volume (" + std::to_string(volume) +
               " m^3): are its triangles wound inward (clockwise seen from outside)?";
    return std::nullopt;
}

} // namespace tumble::physics
