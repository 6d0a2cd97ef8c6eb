#pragma once
// State: what changes each step (MuJoCo's mjData). Made by initial_state() (build.h), then written
// only by step() (step.h), field by field as said below; between steps a caller may copy or set it
// (a saved state, an exact reference). Plain flat arrays, so saving a state is a copy and a
// restored copy continues bit-identically.
#include "physics/contact_cache.h"
#include "physics/math.h"

#include <cstdint>
#include <vector>

namespace tumble::physics {

struct Model;

struct State {
    // Steps taken, counted by step(); the time is t = step * dt (no accumulated round-off).
    std::int64_t step = 0;

    // Per body. Written by the named integrator (integrator_<name>.cpp) and, in a scene with
    // contacts, by the contact stage around it (step.cpp): the impacts and the substeps change v
    // and w of the bodies in contact and set their x to x + h' v_solved after the integrator;
    // sleeping bodies get their x and q put back after it, with v = w = 0; isolated impacts shift x
    // once the substeps are done; the sleep stage sets v = w = 0 for the bodies it puts to sleep.
    std::vector<Vec3> x; // centre of mass, world, m
    std::vector<Quat> q; // orientation of the mass frame, body -> world, unit quaternion
    std::vector<Vec3> v; // linear velocity of the centre of mass, world, m/s
    std::vector<Vec3> w; // angular velocity, world, rad/s
    // Kahan carry of x: the low-order bits the last position update could not hold, fed back into
    // the next one (compensated.h), so tiny steps far from the origin do not lose their increments.
    // Written only by the integrators' position updates; where the contact stage sets x outright
    // it leaves the carry as it is (compensated.h says why that is harmless).
    std::vector<Vec3> x_carry;

    // Written only by the contact stage (contact_cache.h): last step's manifolds and impulses
    // (contact_store.cpp), and sleeping (contact_wake.cpp, contact_sleep.cpp).
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
