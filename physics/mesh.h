#pragma once
// Closed triangle meshes (the app loads them from OBJ files; physics only sees the triangles) and
// their exact mass properties.
#include "physics/math.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tumble::physics {

// Triangles index `vertices` and are wound counter-clockwise seen from outside, so the right-hand
// normal (p1 - p0) x (p2 - p0) points out of the solid. Coordinates are in the body frame, m.
struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
};

// Mass properties of the solid a closed mesh bounds, at unit density (1 kg/m^3): multiply
// `volume` and `inertia` by the density (or by m / volume) for a body.
struct MeshMassProperties {
    double volume = 0.0;          // m^3
    Vec3 centroid = Vec3::Zero(); // centre of mass, body frame, m
    Mat3 inertia = Mat3::Zero();  // about the centroid, body axes, per unit density (m^5)
};

// Exact for any closed polyhedron (Mirtich 1996, "Fast and Accurate Computation of Polyhedral
// Mass Properties"; in the compact per-triangle form of Eberly, "Polyhedral Mass Properties
// (Revisited)", 2002). Assumes a mesh that passed check_closed_mesh().
MeshMassProperties mesh_mass_properties(const TriangleMesh& mesh);

// Why `mesh` does not bound a solid, or nothing: needs at least 4 vertices and 4 triangles, finite
// coordinates, valid indices, no degenerate triangle, every edge shared by exactly two triangles
// that traverse it in opposite directions (closed and consistently wound), and positive volume
// (negative volume: the triangles are wound inward).
std::optional<std::string> check_closed_mesh(const TriangleMesh& mesh);

} // namespace tumble::physics
