#pragma once
// Collision and drawing shapes, described in the body frame, and their mass properties.
#include "physics/math.h"

#include <cstdint>

namespace tumble::physics {

enum class ShapeKind : std::uint8_t { Sphere, Box, Plane, Capsule, Mesh };

// Sphere: `radius`. Box: `half_extents` along the body axes. Plane: the body's z = 0 plane with
// normal +z, infinite, static only (it has no volume and no mass). Capsule: the points within
// `radius` of the segment from (0, 0, -half_length) to (0, 0, +half_length) (a cylinder of length
// 2 half_length capped by two hemispheres). Mesh: a closed triangle mesh (BodyDef::mesh); it
// collides as the convex polyhedron it must be.
struct Shape {
    ShapeKind kind = ShapeKind::Sphere;
    double radius = 0.5;
    Vec3 half_extents = Vec3(0.5, 0.5, 0.5);
    double half_length = 0.0;

    static Shape sphere(double radius) { return {ShapeKind::Sphere, radius, Vec3::Zero()}; }
    static Shape box(const Vec3& half_extents) { return {ShapeKind::Box, 0.0, half_extents}; }
    static Shape plane() { return {ShapeKind::Plane, 0.0, Vec3::Zero()}; }
    static Shape capsule(double radius, double half_length) {
        return {ShapeKind::Capsule, radius, Vec3::Zero(), half_length};
    }
    static Shape mesh() { return {ShapeKind::Mesh, 0.0, Vec3::Zero()}; }
};

const char* shape_name(ShapeKind kind);

// Volume in m^3 (0 for a plane; for a mesh use mesh_mass_properties(), which needs the triangles).
double shape_volume(const Shape& shape);

// Principal moments of inertia (kg m^2) of a solid, uniform-density shape of mass m about its
// centre, along the body axes (for these shapes the body axes are principal):
//   sphere of radius r:            I = 2/5 m r^2 (all three)
//   box of half extents (a, b, c): I1 = m/3 (b^2 + c^2), I2 = m/3 (a^2 + c^2), I3 = m/3 (a^2 + b^2)
// (the box formula is the textbook m/12 (h^2 + d^2) with full lengths h = 2b, d = 2c).
//   capsule (radius r, cylinder length L = 2 half_length), split into a cylinder of mass m_c and
//   two hemispheres of mass m_h each, in proportion to their volumes pi r^2 L and 2/3 pi r^3:
//     I3 (axis) = m_c r^2 / 2 + 2 m_h (2/5 r^2)
//     I1 = I2   = m_c (L^2/12 + r^2/4) + 2 m_h (2/5 r^2 + L^2/4 + 3/8 L r)
//   (a hemisphere's moment about a diameter of its flat face is 2/5 m_h r^2; its centre of mass
//   sits 3/8 r from that face, so the parallel-axis theorem to the capsule centre, L/2 away from
//   the face, gives 2/5 r^2 - (3/8 r)^2 + (L/2 + 3/8 r)^2 = 2/5 r^2 + L^2/4 + 3/8 L r.)
// Mesh: zero here; build_model() integrates the mesh (mesh_mass_properties).
Vec3 shape_principal_inertia(const Shape& shape, double mass);

} // namespace tumble::physics
