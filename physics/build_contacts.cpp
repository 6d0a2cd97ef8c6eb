#include "physics/build_contacts.h"

#include <cmath>

namespace tumble::physics {
namespace {

const TriangleMesh& checked_mesh(const BodyDef& b, int i) {
    require(b.mesh != nullptr, i, "file", "a mesh body needs its triangles");
    if (auto why = check_closed_mesh(*b.mesh)) throw ModelError(i, "file", *why);
    return *b.mesh;
}

} // namespace

void validate_contact_settings(const ContactSettings& s) {
    require(s.substeps >= 0 && s.substeps <= 64, -1, "substeps",
            "substeps must be 0 (on demand) or 1..64");
    require(s.iterations >= 0 && s.iterations <= 64, -1, "iterations",
            "iterations must be 0 (on demand) or 1..64 solve sweeps per substep");
    require(std::isfinite(s.tolerance) && s.tolerance > 0.0, -1, "contact_tolerance",
            "the contact tolerance must be a positive length in m");
    require(s.relax_iterations >= 1 && s.relax_iterations <= 64, -1, "relax_iterations",
            "relax_iterations must be 1..64 sweeps per substep");
    require(std::isfinite(s.restitution_threshold) && s.restitution_threshold >= 0.0, -1,
            "restitution_threshold", "the restitution threshold must be a speed >= 0 in m/s");
}

Vec3 mesh_centroid(const BodyDef& b, int i) {
    return mesh_mass_properties(checked_mesh(b, i)).centroid;
}

Mat3 mesh_inertia(const BodyDef& b, int i) {
    const MeshMassProperties p = mesh_mass_properties(checked_mesh(b, i));
    return (b.mass / p.volume) * p.inertia; // density = m / V
}

void add_contact_geometry(Model& m, const BodyDef& b, int i) {
    require(std::isfinite(b.material.friction) && b.material.friction >= 0.0, i, "friction",
            "friction must be a finite coefficient >= 0");
    require(std::isfinite(b.material.restitution) && b.material.restitution >= 0.0 &&
                b.material.restitution <= 1.0,
            i, "restitution", "restitution must be in [0, 1] (0: no bounce, 1: elastic)");
    m.material.push_back(b.material);

    const Shape& s = b.shape;
    int hull = -1;
    double swing = 0.0;
    switch (s.kind) {
    case ShapeKind::Box:
        hull = static_cast<int>(m.hulls.size());
        m.hulls.push_back(make_box_hull(s.half_extents));
        swing = s.half_extents.norm();
        break;
    case ShapeKind::Mesh: {
        ConvexHull h;
        if (auto why = make_mesh_hull(checked_mesh(b, i), h)) throw ModelError(i, "file", *why);
        const Vec3 com = m.com_offset[i];
        for (const Vec3& v : h.vertices) swing = std::max(swing, (v - com).norm());
        hull = static_cast<int>(m.hulls.size());
        m.hulls.push_back(std::move(h));
        break;
    }
    case ShapeKind::Capsule:
        swing = s.half_length;
        break;
    case ShapeKind::Sphere:
    case ShapeKind::Plane:
        break;
    }
    m.hull.push_back(hull);
    m.swing.push_back(swing);
}

} // namespace tumble::physics
