#pragma once
// State: what changes each step (MuJoCo's mjData), written only by the integrators. Plain flat
// arrays, so saving a state is a copy and a restored copy continues bit-identically.
#include "physics/contact_cache.h"
#include "physics/math.h"

#include <cstdint>
#include <vector>

namespace tumble::physics {

struct Model;

struct State {
    std::int64_t step = 0; // steps taken; the time is t = step * dt (no accumulated round-off)
    std::vector<Vec3> x;   // centre of mass, world, m
    std::vector<Quat> q;   // orientation of the mass frame, body -> world, unit quaternion
    std::vector<Vec3> v;   // linear velocity of the centre of mass, world, m/s
    std::vector<Vec3> w;   // angular velocity, world, rad/s
    // Kahan carry of x: the low-order bits the last position update could not hold, fed back into
    // the next one (compensated.h), so tiny steps far from the origin do not lose their increments.
    std::vector<Vec3> x_carry;

    // Contact stage only (contact_cache.h): last step's manifolds and impulses, and sleeping.
    ContactCache contacts;
    SleepState sleep;

    double time(const Model& model) const;
};

// Position and orientation of body i's *body* frame (the frame the scene file and the renderer
// use), from its mass-frame state: R_body = R_mass * body_from_mass^-1, origin = x - R_body c.
struct Pose {
    Vec3 position;
    Quat orientation;
};
Pose body_pose(const Model& model, const State& state, int body);

} // namespace tumble::physics
