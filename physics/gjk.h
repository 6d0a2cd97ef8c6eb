#pragma once
// Distance between two convex polytopes given as point sets (the convex hulls of `a` and `b`):
// the Gilbert-Johnson-Keerthi algorithm (GJK, 1988) on the Minkowski difference A - B. The
// closest point of A - B to the origin is found on a simplex of at most four support points,
// refined until a new support point brings it no closer. Used for the separated cases of
// sphere-hull and capsule-hull contacts; overlapping cores go to the separating-axis test.
#include "physics/math.h"

#include <span>

namespace tumble::physics {

struct GjkResult {
    double distance = 0.0;                               // 0 when the hulls overlap
    Vec3 point_a = Vec3::Zero(), point_b = Vec3::Zero(); // closest points
    bool overlap = false;
};

GjkResult gjk_distance(std::span<const Vec3> a, std::span<const Vec3> b);

} // namespace tumble::physics
