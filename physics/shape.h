#pragma once
// Collision and drawing shapes, described in the body frame, and their mass properties.
#include "physics/math.h"

#include <cstdint>

namespace tumble::physics {

enum class ShapeKind : std::uint8_t { Sphere, Box, Plane };

// Sphere: `radius`. Box: `half_extents` along the body axes. Plane: the body's z = 0 plane with
// normal +z, infinite, static only (it has no volume and no mass).
struct Shape {
    ShapeKind kind = ShapeKind::Sphere;
    double radius = 0.5;
    Vec3 half_extents = Vec3(0.5, 0.5, 0.5);

    static Shape sphere(double radius) { return {ShapeKind::Sphere, radius, Vec3::Zero()}; }
    static Shape box(const Vec3& half_extents) { return {ShapeKind::Box, 0.0, half_extents}; }
    static Shape plane() { return {ShapeKind::Plane, 0.0, Vec3::Zero()}; }
};

const char* shape_name(ShapeKind kind);

// Volume in m^3 (0 for a plane).
double shape_volume(const Shape& shape);

// Principal moments of inertia (kg m^2) of a solid, uniform-density shape of mass m about its
// centre, along the body axes (for these shapes the body axes are principal):
//   sphere of radius r:            I = 2/5 m r^2 (all three)
//   box of half extents (a, b, c): I1 = m/3 (b^2 + c^2), I2 = m/3 (a^2 + c^2), I3 = m/3 (a^2 + b^2)
// (the box formula is the textbook m/12 (h^2 + d^2) with full lengths h = 2b, d = 2c).
Vec3 shape_principal_inertia(const Shape& shape, double mass);

} // namespace tumble::physics
