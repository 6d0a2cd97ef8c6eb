#pragma once
// The exact motion of one body of a physics Model from a given state, for the cases that have one:
// the centre of mass as a projectile under gravity and the applied force, and the rotation as a
// torque-free body (any inertia) or a sphere under a torque parallel to its spin. Bodies interact
// with nothing here: valid while there are no contacts.
#include "physics/exact/free_rigid_body.h"
#include "physics/exact/simple_motions.h"
#include "physics/model.h"
#include "physics/state.h"

#include <optional>

namespace tumble::exact {

struct BodyState {
    Vec3 x; // centre of mass, world
    Quat q; // mass frame, body -> world
    Vec3 v; // world
    Vec3 w; // world
};

class ExactBodyMotion {
  public:
    // Starts from state.{x, q, v, w}[body] at t = 0 (times are relative to `state`). Throws
    // std::invalid_argument for a static body, std::domain_error when the rotation has no closed
    // form here (a torque on a non-isotropic body, or a torque not parallel to the spin, or the
    // separatrix of a free asymmetric body).
    ExactBodyMotion(const physics::Model& model, const physics::State& state, int body);

    BodyState at(double t) const;
    const ExactFreeRigidBody* free_rotation() const { return free_ ? &*free_ : nullptr; }

  private:
    Projectile translation_;
    std::optional<ExactFreeRigidBody> free_;
    std::optional<ConstantTorqueSphere> torqued_;
};

} // namespace tumble::exact
