#include "physics/scenes/reference_scenes.h"

#include <algorithm>
#include <cmath>

namespace tumble::scenes {

using physics::BodyDef;
using physics::Quat;
using physics::Shape;
using physics::Vec3;

BodyDef book() {
    BodyDef b;
    b.shape = Shape::box(Vec3(0.11, 0.025, 0.15));
    b.mass = 0.8; // I = (6.17e-3, 9.23e-3, 3.39e-3) kg m^2: x is the middle axis
    return b;
}

Scene intermediate_axis_scene() {
    Scene s;
    s.name = "intermediate-axis";
    s.world.gravity = Vec3::Zero();
    BodyDef b = book();
    b.angular_velocity = Vec3(6.0, 0.05, 0.05); // body axes = world axes at t = 0
    s.bodies = {b};
    s.duration = 2.5;
    return s;
}

Scene tumbling_box_scene() {
    Scene s;
    s.name = "tumbling-box";
    s.world.gravity = Vec3::Zero();
    BodyDef b;
    b.shape = Shape::box(Vec3(0.1, 0.2, 0.3));
    b.mass = 1.0;
    b.angular_velocity = Vec3(1.0, 2.0, 3.0);
    s.bodies = {b};
    s.duration = 5.0;
    return s;
}

Scene gravity_spin_scene() {
    Scene s;
    s.name = "gravity-and-spin";
    s.world.gravity = Vec3(0.0, 0.0, -9.81);
    BodyDef thrown = book();
    thrown.position = Vec3(0.0, 0.0, 1.0);
    thrown.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3(1.0, 2.0, 0.5).normalized()));
    thrown.velocity = Vec3(0.6, -0.2, 4.5);
    thrown.angular_velocity = thrown.orientation * Vec3(0.8, 5.0, -0.6); // mostly the largest axis
    BodyDef ball;
    ball.shape = Shape::sphere(0.12);
    ball.mass = 0.5;
    ball.position = Vec3(-1.0, 0.5, 0.5);
    ball.velocity = Vec3(0.5, 0.0, 3.0);
    ball.angular_velocity = Vec3(1.0, -2.0, 2.0);
    ball.applied_torque = 0.004 * Vec3(1.0, -2.0, 2.0); // parallel to the spin: exact oracle
    s.bodies = {thrown, ball};
    s.duration = 1.0;
    return s;
}

Scene torque_free_spheres(int count) {
    Scene s;
    s.name = "torque-free-spheres";
    s.world.gravity = Vec3::Zero();
    // Every pair separates: relative velocity 0.2/s d + (0, 0, dz) with d in the plane z = 0, so
    // d . (relative velocity) = 0.2/s |d|^2 > 0 from the start.
    const Vec3 centre(0.15 * (std::min(count, 40) - 1), 0.15 * ((count - 1) / 40), 0.0);
    for (int i = 0; i < count; ++i) {
        BodyDef b;
        b.shape = Shape::sphere(0.1);
        b.mass = 1.0;
        const double a = 0.7 * i;
        b.position = Vec3(0.3 * (i % 40), 0.3 * (i / 40), 0.0);
        b.velocity = 0.2 * (b.position - centre) + Vec3(0.0, 0.0, 0.1 * std::sin(a));
        b.angular_velocity = Vec3(std::cos(a), std::sin(1.3 * a), 0.5) * 4.0;
        s.bodies.push_back(b);
    }
    s.duration = 1.0;
    return s;
}

} // namespace tumble::scenes
