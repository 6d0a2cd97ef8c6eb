#include "physics/scenes/sphere_rain.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace tumble::scenes {

using physics::BodyDef;
using physics::Vec3;

double rain_hash(std::uint32_t i, std::uint32_t k) {
    std::uint32_t h = i * 2654435761u + k * 0x9E3779B9u;
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return static_cast<double>(h) / 4294967296.0 * 2.0 - 1.0;
}

namespace {

// The floor, then the walls: x = +-2 over the full length, y = +-2 between them.
void add_floor_and_walls(Scene& s) {
    BodyDef floor;
    floor.shape = physics::Shape::plane();
    floor.motion = physics::Motion::Static;
    s.bodies.push_back(floor);
    const double t = 0.05; // half thickness of a wall
    for (int side = -1; side <= 1; side += 2) {
        BodyDef wx; // x = +-2, full length
        wx.shape = physics::Shape::box(Vec3(t, 2.0 + 2.0 * t, 0.5));
        wx.motion = physics::Motion::Static;
        wx.position = Vec3(side * (2.0 + t), 0.0, 0.5);
        s.bodies.push_back(wx);
    }
    for (int side = -1; side <= 1; side += 2) {
        BodyDef wy; // y = +-2, between the x walls
        wy.shape = physics::Shape::box(Vec3(2.0, t, 0.5));
        wy.motion = physics::Motion::Static;
        wy.position = Vec3(0.0, side * (2.0 + t), 0.5);
        s.bodies.push_back(wy);
    }
}

} // namespace

Scene sphere_rain(int n, bool shifted) {
    Scene s;
    s.name = shifted ? "sphere-rain" : "sphere-columns";
    s.world.dt = 1.0 / 240.0;
    s.world.gravity = Vec3(0.0, 0.0, -9.81);
    s.world.contact.sleeping = false;
    s.duration = 5.0;
    add_floor_and_walls(s);
    const double spacing = 0.12, centre = 0.5 * (n - 1) * spacing;
    for (int i = 0; i < n * n * n; ++i) {
        const int ix = i % n, iy = (i / n) % n, iz = i / (n * n);
        BodyDef b;
        b.shape = physics::Shape::sphere(0.05);
        b.mass = 0.1;
        b.material = {0.5, 0.3};
        const std::uint32_t u = static_cast<std::uint32_t>(i);
        const double dx = shifted ? 0.01 * rain_hash(u, 0) : 0.0;
        const double dy = shifted ? 0.01 * rain_hash(u, 1) : 0.0;
        b.position =
            Vec3(ix * spacing - centre + dx, iy * spacing - centre + dy, 0.5 + iz * spacing);
        s.bodies.push_back(b);
    }
    return s;
}

RainEnd judge_rain(const physics::State& s) {
    constexpr double r = 0.05, m = 0.1, wall = 2.0, cell = 2.0 * r;
    RainEnd e;
    const int first = kRainFirstSphere, n = static_cast<int>(s.x.size());
    std::unordered_map<std::int64_t, std::vector<int>> grid; // spheres by cell of size 2r
    auto key = [](std::int64_t ix, std::int64_t iy, std::int64_t iz) {
        return (ix + (1 << 20)) << 42 | (iy + (1 << 20)) << 21 | (iz + (1 << 20));
    };
    auto cell_of = [&](double v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
    for (int i = first; i < n; ++i) {
        const Vec3& x = s.x[i];
        e.outside += std::abs(x.x()) > wall || std::abs(x.y()) > wall || x.z() < 0.0;
        e.max_penetration = std::max({e.max_penetration, r - x.z(), x.x() + r - wall,
                                      -wall - (x.x() - r), x.y() + r - wall, -wall - (x.y() - r)});
        e.kinetic_energy +=
            0.5 * m * s.v[i].squaredNorm() + 0.5 * 0.4 * m * r * r * s.w[i].squaredNorm();
        grid[key(cell_of(x.x()), cell_of(x.y()), cell_of(x.z()))].push_back(i);
    }
    for (int i = first; i < n; ++i) {
        const Vec3& x = s.x[i];
        const std::int64_t cx = cell_of(x.x()), cy = cell_of(x.y()), cz = cell_of(x.z());
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = grid.find(key(cx + dx, cy + dy, cz + dz));
                    if (it == grid.end()) continue;
                    for (int j : it->second)
                        if (j > i)
                            e.max_penetration =
                                std::max(e.max_penetration, 2.0 * r - (s.x[j] - x).norm());
                }
    }
    return e;
}

} // namespace tumble::scenes
