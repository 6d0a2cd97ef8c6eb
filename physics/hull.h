#pragma once
// Convex polyhedra for collision: boxes and convex meshes share one representation, so box-box,
// box-mesh and mesh-mesh contacts use one separating-axis test and one clipping routine.
// Coordinates are in the body frame. Faces are planar convex polygons wound counter-clockwise
// seen from outside; coplanar mesh triangles are merged into one face so that a flat side gives
// one stable 4-point manifold, not a flickering choice between its triangles.
#include "physics/mesh.h"

#include <optional>
#include <string>
#include <vector>

namespace tumble::physics {

struct HullFace {
    Vec3 normal;      // unit, outward
    double offset;    // plane: normal . p = offset
    int first, count; // vertex loop: face_vertices[first .. first + count)
};

// An edge between two faces. Walking from v0 to v1, `left` is the face that traverses it in that
// direction (its outward normal n_left satisfies (v1 - v0) x n_left pointing away from it).
struct HullEdge {
    int v0, v1;
    int left, right;
};

struct ConvexHull {
    std::vector<Vec3> vertices;
    std::vector<HullFace> faces;
    std::vector<int> face_vertices;
    std::vector<HullEdge> edges;
    Vec3 centroid = Vec3::Zero(); // of the vertices: a point strictly inside
    Vec3 box_min = Vec3::Zero();  // local bounding box
    Vec3 box_max = Vec3::Zero();
    double radius = 0.0; // largest distance of a vertex from the body origin, m
};

// The box [-h, h] (6 quadrilateral faces, 12 edges).
ConvexHull make_box_hull(const Vec3& half_extents);

// The hull of a closed, convex mesh (check_closed_mesh() passed). Refuses, with a message, a mesh
// whose vertices lie more than 1e-6 of its size outside the plane of one of its triangles:
// contacts treat the mesh as the convex polyhedron it bounds, which must be the mesh itself.
std::optional<std::string> make_mesh_hull(const TriangleMesh& mesh, ConvexHull& out);

} // namespace tumble::physics
