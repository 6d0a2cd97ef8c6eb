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
    }
    return "unknown";
}

double shape_volume(const Shape& shape) {
    switch (shape.kind) {
    case ShapeKind::Sphere:
        return 4.0 / 3.0 * std::numbers::pi * shape.radius * shape.radius * shape.radius;
    case ShapeKind::Box:
        return 8.0 * shape.half_extents.prod();
    case ShapeKind::Plane:
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
    case ShapeKind::Plane:
        return Vec3::Zero();
    }
    return Vec3::Zero();
}

} // namespace tumble::physics
