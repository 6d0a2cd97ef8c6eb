#include "physics/scenes/stability_scenes.h"
#include "physics/scenes/ground.h"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace tumble::scenes {

using physics::BodyDef;
using physics::Quat;
using physics::Shape;
using physics::TriangleMesh;
using physics::Vec3;

namespace {

Scene on_ground(const char* name, double dt, int substeps) {
    Scene s;
    s.name = name;
    s.world.dt = dt;
    s.world.contact.sleeping = false;
    s.world.contact.substeps = substeps;
    s.bodies = {ground()};
    return s;
}

BodyDef cube(double mass, double z) {
    BodyDef b;
    b.shape = Shape::box(Vec3(0.1, 0.1, 0.1));
    b.mass = mass;
    b.position = Vec3(0, 0, z);
    return b;
}

} // namespace

Scene mass_ratio_stack(double ratio, double dt, int substeps) {
    Scene s = on_ground("mass-ratio-stack", dt, substeps);
    s.bodies.push_back(cube(1.0, 0.1));
    s.bodies.push_back(cube(ratio, 0.3));
    return s;
}

std::shared_ptr<const TriangleMesh> sharp_top_mesh(int segments) {
    // Rings of the profile (r, z) above the apex; the apex closes the bottom, a centre vertex the
    // crown. Counter-clockwise seen from outside: the ring quads as in scripts/make-meshes.py.
    const std::vector<std::pair<double, double>> rings{
        {0.040, 0.030}, {0.040, 0.036}, {0.008, 0.056}};
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->vertices.push_back(Vec3::Zero()); // the tip
    for (const auto& [r, z] : rings)
        for (int k = 0; k < segments; ++k) {
            const double a = 2.0 * std::numbers::pi * k / segments;
            mesh->vertices.emplace_back(r * std::cos(a), r * std::sin(a), z);
        }
    const int crown = static_cast<int>(mesh->vertices.size());
    mesh->vertices.emplace_back(0.0, 0.0, rings.back().second);
    const auto ring = [&](int i, int k) { return 1 + i * segments + (k % segments); };
    for (int k = 0; k < segments; ++k) {
        mesh->triangles.push_back({0, ring(0, k + 1), ring(0, k)});
        for (int i = 0; i + 1 < static_cast<int>(rings.size()); ++i) {
            mesh->triangles.push_back({ring(i, k), ring(i, k + 1), ring(i + 1, k + 1)});
            mesh->triangles.push_back({ring(i, k), ring(i + 1, k + 1), ring(i + 1, k)});
        }
        const int last = static_cast<int>(rings.size()) - 1;
        mesh->triangles.push_back({crown, ring(last, k), ring(last, k + 1)});
    }
    return mesh;
}

Scene fast_top(double spin, double dt, int substeps) {
    Scene s = on_ground("fast-top", dt, substeps);
    s.bodies[0].material.friction = 1.0;
    BodyDef top;
    top.shape = Shape::mesh();
    top.mesh = sharp_top_mesh();
    const physics::MeshMassProperties mp = physics::mesh_mass_properties(*top.mesh);
    top.mass = 1200.0 * mp.volume;
    top.orientation = Quat(Eigen::AngleAxisd(15.0 * std::numbers::pi / 180.0, Vec3::UnitX()));
    top.position = Vec3(0, 0, 3e-4); // the tip 0.3 mm above the table
    top.angular_velocity = top.orientation * Vec3(0, 0, spin);
    top.material.friction = 1.0;
    s.bodies.push_back(top);
    s.duration = 10.0;
    return s;
}

Scene resting_ball(double dt, int substeps) {
    Scene s = on_ground("resting-ball", dt, substeps);
    BodyDef ball;
    ball.shape = Shape::sphere(0.1);
    ball.mass = 1.0;
    ball.position = Vec3(0, 0, 0.1);
    s.bodies.push_back(ball);
    s.duration = 10.0;
    return s;
}

} // namespace tumble::scenes
