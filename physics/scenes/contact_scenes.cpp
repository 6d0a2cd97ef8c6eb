#include "physics/scenes/contact_scenes.h"

#include "physics/scenes/ground.h"

namespace tumble::scenes {

using physics::BodyDef;
using physics::Quat;
using physics::Shape;
using physics::Vec3;

Scene ball_drop(double restitution, double h0, double dt) {
    Scene s;
    s.name = "ball-drop";
    s.world.dt = dt;
    BodyDef ball;
    ball.shape = Shape::sphere(kDropBallRadius);
    ball.mass = 1.0;
    ball.position = Vec3(0, 0, kDropBallRadius + h0);
    ball.material.restitution = restitution;
    s.bodies = {ground(), ball};
    return s;
}

Scene incline(double angle, double mu, double dt, bool sleeping) {
    Scene s;
    s.name = "incline";
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

Scene box_stack(int n, double edge, double dt) {
    Scene s;
    s.name = "box-stack";
    s.world.dt = dt;
    s.world.contact.sleeping = false;
    s.bodies = {ground()};
    const double half = 0.5 * edge;
    for (int i = 0; i < n; ++i) {
        BodyDef b;
        b.shape = Shape::box(Vec3(half, half, half));
        b.mass = 1.0;
        b.position = Vec3(0, 0, half + edge * i);
        s.bodies.push_back(b);
    }
    return s;
}

Scene pyramid(double dt) {
    Scene s;
    s.name = "pyramid";
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

Scene cradle(double speed, double dt) {
    Scene s;
    s.name = "cradle";
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

Scene bullet(double speed, double dt) {
    Scene s;
    s.name = "bullet";
    s.world.dt = dt;
    s.world.gravity = Vec3::Zero();
    BodyDef wall;
    wall.shape = Shape::box(Vec3(0.005, 0.5, 0.5));
    wall.motion = physics::Motion::Static;
    BodyDef ball;
    ball.shape = Shape::sphere(0.02);
    ball.mass = 0.01;
    ball.position = Vec3(-1.0, 0, 0);
    ball.velocity = Vec3(speed, 0, 0);
    s.bodies = {wall, ball};
    return s;
}

} // namespace tumble::scenes
