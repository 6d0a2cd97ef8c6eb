#pragma once
// Narrow phase: the contact manifold of two shapes. One function per pair of shape families,
// dispatched once per pair (a switch, no virtual calls); every pair of Tumble's shapes is covered.
//
// Conventions (Box2D's): the manifold normal is a unit vector from body A to body B; a point
// lies midway between the two surfaces, its `separation` is the signed gap along the normal
// (negative: overlap). Points farther apart than `margin` are dropped, so a manifold may hold
// speculative points that are not touching yet: the solver keeps them from closing faster than
// the gap allows (speculative contacts, Box2D v3). `id` names the features that made the point
// (vertex, edge, face indices), so the same contact keeps its id from step to step and its
// impulse can warm-start the solver; ids only need to be stable, not meaningful.
#include "physics/model.h"

#include <cstdint>

namespace tumble::physics {

struct ContactPoint {
    Vec3 point;        // world, m
    double separation; // m
    std::uint32_t id;
};

struct Manifold {
    Vec3 normal = Vec3::UnitZ(); // world, unit, from A to B
    int count = 0;               // 0 (no contact) .. 4
    ContactPoint points[4];
};

// Where a body's shape is: its body frame (the frame shapes are described in), world.
struct ShapePose {
    Vec3 position;
    Mat3 rotation;
};

ShapePose shape_pose(const Model& model, const Vec3& x, const Quat& q, int body);

// Axis-aligned bounding box of a body's shape at `pose` (not for planes: they are unbounded).
struct Aabb {
    Vec3 lo, hi;
};
Aabb shape_aabb(const Model& model, int body, const ShapePose& pose);

// Half the thinnest extent of a body's shape (radius, smallest half extent, ...), m: the scale
// that "deep" overlap is measured against.
double shape_thickness(const Model& model, int body);

// The manifold of bodies a and b (any order of shape kinds; planes and statics included).
void collide(const Model& model, int a, const ShapePose& pa, int b, const ShapePose& pb,
             double margin, Manifold& out);

// Lowest point of body i's shape along -n relative to the plane n.x = offset: min over the shape
// of n.x - offset (negative: the shape crosses the plane). Planes themselves: -infinity.
double plane_clearance(const Model& model, int i, const ShapePose& pose, const Vec3& n,
                       double offset);

// Shape-pair families, body frames as given; each writes a manifold with normal from the first
// shape to the second. Used by collide() and by the tests.
void collide_spheres(const Vec3& ca, double ra, const Vec3& cb, double rb, double margin,
                     Manifold& out);
void collide_plane_sphere(const Vec3& n, double offset, const Vec3& c, double r, double margin,
                          Manifold& out);
void collide_capsule_sphere(const Vec3& p0, const Vec3& p1, double ra, const Vec3& c, double rb,
                            double margin, Manifold& out);
void collide_capsules(const Vec3& a0, const Vec3& a1, double ra, const Vec3& b0, const Vec3& b1,
                      double rb, double margin, Manifold& out);
void collide_plane_capsule(const Vec3& n, double offset, const Vec3& p0, const Vec3& p1, double r,
                           double margin, Manifold& out);
void collide_plane_hull(const Vec3& n, double offset, const ConvexHull& hull, const ShapePose& pose,
                        double margin, Manifold& out);
void collide_hulls(const ConvexHull& ha, const ShapePose& pa, const ConvexHull& hb,
                   const ShapePose& pb, double margin, Manifold& out);
void collide_hull_sphere(const ConvexHull& hull, const ShapePose& pose, const Vec3& c, double r,
                         double margin, Manifold& out);
void collide_hull_capsule(const ConvexHull& hull, const ShapePose& pose, const Vec3& p0,
                          const Vec3& p1, double r, double margin, Manifold& out);

// Keeps at most 4 of `count` points: the deepest, then those spanning the largest area (the
// points that best resist tipping), in a fixed order (deterministic).
int reduce_manifold(const Vec3& normal, ContactPoint* points, int count);

} // namespace tumble::physics
