#pragma once
// Building a Model and its initial State from plain descriptions. The app fills these from a
// scene file; physics validates what only physics can judge and names the body and field.
#include "physics/mesh.h"
#include "physics/model.h"
#include "physics/state.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace tumble::physics {

struct WorldDef {
    Vec3 gravity = Vec3(0.0, 0.0, -9.81);
    double dt = 1.0 / 240.0;
    Integrator integrator = Integrator::Rk4;
    ContactSettings contact;     // sleeping, substeps, restitution threshold (contact_model.h)
    std::vector<Damper> dampers; // viscous rotary dampers between bodies (damper.h)
};

struct BodyDef {
    Shape shape;
    Motion motion = Motion::Dynamic;
    double mass = 1.0; // kg; ignored for static bodies
    // Inertia tensor about the centre of mass in body axes, kg m^2. All zero (the default): from
    // shape and mass. May be non-diagonal; build_model() diagonalises it (moments + axes).
    Mat3 inertia = Mat3::Zero();
    Vec3 position = Vec3::Zero();         // body origin, world, m
    Quat orientation = Quat::Identity();  // body -> world
    Vec3 velocity = Vec3::Zero();         // world, m/s
    Vec3 angular_velocity = Vec3::Zero(); // world, rad/s
    double gravity_scale = 1.0;
    Vec3 applied_force = Vec3::Zero();  // constant, world, N
    Vec3 applied_torque = Vec3::Zero(); // constant, world, N m
    Material material;                  // friction, restitution (contact_model.h)
    // Shape::mesh() only: the closed triangle mesh, body frame (shared by bodies that reuse it).
    // Its centroid becomes the centre of mass and its inertia comes from the exact polyhedral
    // integrals (mesh.h) unless `inertia` is given.
    std::shared_ptr<const TriangleMesh> mesh;
};

// Thrown for a definition physics cannot simulate. `body` is the index (-1 for the world) and
// `field` names the offending field as the scene format spells it (e.g. "inertia", "mass").
struct ModelError : std::runtime_error {
    ModelError(int body, std::string field, const std::string& what)
        : std::runtime_error(what), body(body), field(std::move(field)) {}
    int body;
    std::string field;
};

// Throws ModelError(body, field, what) unless `ok` (the checks of build.cpp and
// build_contacts.cpp).
void require(bool ok, int body, const char* field, const std::string& what);

Model build_model(const WorldDef& world, const std::vector<BodyDef>& bodies);
State initial_state(const Model& model, const std::vector<BodyDef>& bodies);

} // namespace tumble::physics
