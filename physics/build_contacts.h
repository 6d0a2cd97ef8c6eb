#pragma once
// The contact side of build_model(): materials, collision polyhedra and mesh mass properties,
// validated with the body and field named (ModelError). Internal to physics/build.cpp.
#include "physics/build.h"

namespace tumble::physics {

void validate_contact_settings(const ContactSettings& settings);

// Mesh bodies: the centroid of the solid (body frame) and its inertia tensor about the centroid
// for the body's mass, from the exact polyhedral integrals. Refuse a mesh that bounds no solid.
Vec3 mesh_centroid(const BodyDef& body, int index);
Mat3 mesh_inertia(const BodyDef& body, int index);

// Appends body `index`'s material, hull (boxes, meshes) and swing radius to the model.
void add_contact_geometry(Model& model, const BodyDef& body, int index);

// Static shapes never move, so two that overlap stay overlapped for ever: almost always a scene
// mistake (a duplicated wall, a ramp sunk into the floor). Throws ModelError naming both bodies
// when two static bodies overlap by more than 1 mm. Defined in overlaps.cpp.
void check_static_overlaps(const Model& model, const State& state);

} // namespace tumble::physics
