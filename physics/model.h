#pragma once
// Model: what the scene *is* (MuJoCo's mjModel). Built once by build_model() (force_all_passes()
// in passes.h may then turn every pass on), read-only while stepping. Bodies are integer handles
// 0..body_count()-1 into flat arrays (Box2D's ids).
//
// Each dynamic body is simulated in its *mass frame*: origin at the centre of mass, axes along
// the principal axes of inertia. There the inertia is diagonal, I_body = diag(I1, I2, I3), and the
// world inertia is I_w = R I_body R^T with R the mass frame's orientation; we keep the three
// principal moments and never form or invert I_w (Jolt's storage):
//   I_w^-1 v = R (I_body^-1 (R^T v)).
// The body frame the user wrote (and the renderer draws) relates to the mass frame by the fixed
// `body_from_mass` rotation and `com_offset`; for spheres and boxes both are identity.
#include "physics/can_touch.h"
#include "physics/contact_model.h"
#include "physics/hull.h"
#include "physics/integrator.h"
#include "physics/math.h"
#include "physics/shape.h"

#include <cstdint>
#include <vector>

namespace tumble::physics {

enum class Motion : std::uint8_t { Static, Dynamic };

// Which stages step() runs, decided once from what the scene contains ("model only what a scene
// requires"). Each flag says why in `tumble explain`.
struct Passes {
    bool gravity = false;       // some dynamic body feels a non-zero g * gravity_scale
    bool applied_loads = false; // some dynamic body has a constant applied force or torque
    bool gyroscopic = false;    // some dynamic body has anisotropic inertia (w x I w != 0)
    bool contacts = false;      // two shapes can touch (can_touch.h; Model::touch says which)
    bool dampers = false;       // some pair of bodies is coupled by a damper (damper.h)
};

// A viscous rotary damper between bodies a and b (damper.h): torque c (w_b - w_a) on a and the
// opposite on b. At most one of the two is static.
struct Damper {
    int a = 0, b = 0;
    double c = 0.0; // N m s
};

struct Model {
    // World parameters.
    Vec3 gravity = Vec3(0.0, 0.0, -9.81); // m/s^2
    double dt = 1.0 / 240.0;              // s, the step h
    Integrator integrator = Integrator::Rk4;

    // Per-body parameters, indexed by body handle.
    std::vector<Shape> shape;
    std::vector<Motion> motion;
    std::vector<double> mass;            // kg (0 for static)
    std::vector<double> inv_mass;        // 1/kg (0 for static)
    std::vector<Vec3> inertia;           // principal moments (I1, I2, I3), kg m^2, mass frame
    std::vector<Vec3> inv_inertia;       // (1/I1, 1/I2, 1/I3); 0 for static
    std::vector<std::uint8_t> isotropic; // I1 == I2 == I3 exactly: w x I w = 0 for every w
    std::vector<double> gravity_scale;   // multiplies gravity for this body (1 = normal)
    std::vector<Vec3> applied_force;     // constant world-frame force at the centre of mass, N
    std::vector<Vec3> applied_torque;    // constant world-frame torque, N m
    std::vector<Quat> body_from_mass;    // rotation taking mass-frame axes to body-frame axes
    std::vector<Vec3> com_offset;        // centre of mass in the body frame, m

    // Contacts (contact_model.h, hull.h); used only when passes.contacts is on.
    std::vector<Material> material; // per body
    std::vector<int> hull;          // per body: index into `hulls` (boxes, meshes), else -1
    std::vector<ConvexHull> hulls;  // body-frame polyhedra
    std::vector<double> swing;      // per body: farthest surface point a rotation moves, m
                                    // (0 for a sphere, half length for a capsule, ...)
    ContactSettings contact;
    TouchReport touch; // why passes.contacts is on or off (can_touch.h)

    std::vector<Damper> dampers; // run after each step (damper.h) when passes.dampers

    // Dynamic bodies only: the integrators and the contact stage loop over this list.
    std::vector<int> dynamic_bodies;

    Passes passes;
    // Every pass on and no per-body shortcut, whatever the scene needs (force_all_passes() in
    // passes.h): the full pipeline that benchmarks and tests compare the assembled step with.
    bool all_passes = false;

    int body_count() const { return static_cast<int>(shape.size()); }
    bool is_dynamic(int body) const { return motion[body] == Motion::Dynamic; }
};

} // namespace tumble::physics
