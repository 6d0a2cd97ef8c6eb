#pragma once
// Small contact scenes shared by the physics tests: built in code, no files.
#include "physics/build.h"
#include "physics/step.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace tumble::physics::test {

struct Scene {
    WorldDef world;
    std::vector<BodyDef> bodies;
};

inline BodyDef ground(double friction = 0.5) {
    BodyDef g;
    g.shape = Shape::plane();
    g.motion = Motion::Static;
    g.material.friction = friction;
    return g;
}

// A ball of radius 0.1 m dropped from rest with its bottom at h0 above a plane.
inline Scene ball_drop(double restitution, double h0, double dt) {
    Scene s;
    s.world.dt = dt;
    BodyDef ball;
    ball.shape = Shape::sphere(0.1);
    ball.mass = 1.0;
    ball.position = Vec3(0, 0, 0.1 + h0);
    ball.material.restitution = restitution;
    s.bodies = {ground(), ball};
    return s;
}

// A 0.2 x 0.2 x 0.1 m box resting on a plane tilted by `angle` about y (downhill is +x rotated),
// both with friction mu.
inline Scene incline(double angle, double mu, double dt, bool sleeping) {
    Scene s;
    s.world.dt = dt;
    s.world.contact.sleeping = sleeping;
    const Quat tilt(Eigen::AngleAxisd(angle, Vec3::UnitY()));
    BodyDef plane = ground(mu);
    plane.orientation = tilt;
    BodyDef box;
    box.shape = Shape::box(Vec3(0.1, 0.1, 0.05));
    box.mass = 1.0;
    box.material.friction = mu;
    box.orientation = tilt;
    box.position = tilt * Vec3(0, 0, 0.05);
    s.bodies = {plane, box};
    return s;
}

// n boxes of 0.5 m stacked on a plane.
inline Scene tower(int n, double dt) {
    Scene s;
    s.world.dt = dt;
    s.world.contact.sleeping = false;
    s.bodies = {ground()};
    for (int i = 0; i < n; ++i) {
        BodyDef b;
        b.shape = Shape::box(Vec3(0.25, 0.25, 0.25));
        b.mass = 1.0;
        b.position = Vec3(0, 0, 0.25 + 0.5 * i);
        s.bodies.push_back(b);
    }
    return s;
}

// A 2D pyramid of 20 boxes of 0.5 m: rows of 6, 5, 4, 3, 2 with 1 cm gaps.
inline Scene pyramid(double dt) {
    Scene s;
    s.world.dt = dt;
    s.world.contact.sleeping = false;
    s.bodies = {ground()};
    for (int row = 0; row < 5; ++row) {
        const int count = 6 - row;
        for (int i = 0; i < count; ++i) {
            BodyDef b;
            b.shape = Shape::box(Vec3(0.25, 0.25, 0.25));
            b.mass = 1.0;
            b.position = Vec3((i - 0.5 * (count - 1)) * 0.51, 0, 0.25 + 0.5 * row);
            s.bodies.push_back(b);
        }
    }
    return s;
}

// Newton's cradle in free space: five touching steel-like balls (e = 1, no friction), the first
// sent in at `speed` from 10 cm away.
inline Scene cradle(double speed, double dt) {
    Scene s;
    s.world.dt = dt;
    s.world.gravity = Vec3::Zero();
    s.world.contact.sleeping = false;
    for (int i = 0; i < 5; ++i) {
        BodyDef b;
        b.shape = Shape::sphere(0.05);
        b.mass = 0.2;
        b.material = {0.0, 1.0};
        b.position = Vec3(0.1 * i, 0, 0);
        s.bodies.push_back(b);
    }
    s.bodies[0].position.x() -= 0.1;
    s.bodies[0].velocity = Vec3(speed, 0, 0);
    return s;
}

// A 2 cm ball fired along +x at `speed` towards a static wall 1 cm thick at x = 0.
inline Scene bullet(double speed, double dt) {
    Scene s;
    s.world.dt = dt;
    s.world.gravity = Vec3::Zero();
    BodyDef wall;
    wall.shape = Shape::box(Vec3(0.005, 0.5, 0.5));
    wall.motion = Motion::Static;
    BodyDef ball;
    ball.shape = Shape::sphere(0.02);
    ball.mass = 0.01;
    ball.position = Vec3(-1.0, 0, 0);
    ball.velocity = Vec3(speed, 0, 0);
    s.bodies = {wall, ball};
    return s;
}

struct Sim {
    Model model;
    State state;
    explicit Sim(const Scene& s) : model(build_model(s.world, s.bodies)) {
        state = initial_state(model, s.bodies);
    }
    void steps(int n) {
        for (int k = 0; k < n; ++k) step(model, state);
    }
    int steps_for(double seconds) const {
        return static_cast<int>(std::lround(seconds / model.dt));
    }
};

} // namespace tumble::physics::test
