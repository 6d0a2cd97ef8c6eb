#include "physics/shape.h"

#include <numbers>

namespace tumble::physics {

const char* shape_name(ShapeKind kind) {
    switch (kind) {
    case ShapeKind::Sphere:
        return "sphere";
    case ShapeKind::Box:
        return "box";
    case ShapeKind::Plane:
        return "plane";
    case ShapeKind::Capsule:
        return "capsule";
    case ShapeKind::Mesh:
        return "mesh";
    }
    return "unknown";
}

namespace {

struct CapsuleParts {
    double cylinder, hemisphere; // volumes, m^3 (one hemisphere)
};

CapsuleParts capsule_parts(const Shape& s) {
    const double r = s.radius, len = 2.0 * s.half_length;
    return {std::numbers::pi * r * r * len, 2.0 / 3.0 * std::numbers::pi * r * r * r};
}

} // namespace

double shape_volume(const Shape& shape) {
    switch (shape.kind) {
    case ShapeKind::Sphere:
        return 4.0 / 3.0 * std::numbers::pi * shape.radius * shape.radius * shape.radius;
    case ShapeKind::Box:
        return 8.0 * shape.half_extents.prod();
    case ShapeKind::Capsule: {
        const CapsuleParts p = capsule_parts(shape);
        return p.cylinder + 2.0 * p.hemisphere;
    }
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
        return 0.0;
    }
    return 0.0;
}

Vec3 shape_principal_inertia(const Shape& shape, double mass) {
    switch (shape.kind) {
    case ShapeKind::Sphere: {
        const double i = 0.4 * mass * shape.radius * shape.radius;
        return Vec3(i, i, i);
    }
    case ShapeKind::Box: {
        const Vec3 e2 = shape.half_extents.cwiseProduct(shape.half_extents);
        return mass / 3.0 * Vec3(e2.y() + e2.z(), e2.x() + e2.z(), e2.x() + e2.y());
    }
    case ShapeKind::Capsule: {
        const CapsuleParts p = capsule_parts(shape);
        const double density = mass / (p.cylinder + 2.0 * p.hemisphere);
        const double mc = density * p.cylinder, mh = density * p.hemisphere;
        const double r = shape.radius, len = 2.0 * shape.half_length;
        const double axial = mc * r * r / 2.0 + 2.0 * mh * (0.4 * r * r);
        const double across = mc * (len * len / 12.0 + r * r / 4.0) +
                              2.0 * mh * (0.4 * r * r + len * len / 4.0 + 3.0 / 8.0 * len * r);
        return Vec3(across, across, axial);
    }
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
        return Vec3::Zero();
    }
    return Vec3::Zero();
}

} // namespace tumble::physics
