#pragma once
// The "sphere rain" benchmark scene of issue 4, built in code so that every size N = n^3 is the
// same scene (the scene file assets/scenes/sphere_rain.json is the case n = 10):
//   a 4 m x 4 m floor plane at z = 0 inside four static walls 1 m high at x = +-2 and y = +-2;
//   n^3 spheres of radius 0.05 m, mass 0.1 kg, friction 0.5, restitution 0.3, at rest on an
//   n x n x n grid with spacing 0.12 m centred over the floor, lowest layer at z = 0.5 m;
//   gravity 9.81 m/s^2 down; dt = 1/240 s; 5 s (1200 steps); sleeping off.
// Sphere i (ix = i mod n, iy = (i div n) mod n, iz = i div n^2) is shifted by 0.01 m u(i, 0) in x
// and 0.01 m u(i, 1) in y, u from the 32-bit hash below, so that the columns topple into a pile
// ("shifted"); with the shift off the spheres stack in columns.
// Walls: boxes 0.1 m thick whose inner faces are the lines x, y = +-2; the x walls run the full
// 4.2 m so that the corners close, the y walls fit between them (static shapes may not overlap).
#include "physics/build.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace tumble::bench {

// u(i, k) in [-1, 1): h = i*2654435761 + k*0x9E3779B9; h ^= h>>16; h *= 0x85EBCA6B; h ^= h>>13;
// h *= 0xC2B2AE35; h ^= h>>16; u = h / 2^32 * 2 - 1 (all in 32-bit unsigned arithmetic).
inline double rain_hash(std::uint32_t i, std::uint32_t k) {
    std::uint32_t h = i * 2654435761u + k * 0x9E3779B9u;
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return static_cast<double>(h) / 4294967296.0 * 2.0 - 1.0;
}

struct RainScene {
    physics::WorldDef world;
    std::vector<physics::BodyDef> bodies; // 0: floor, 1..4: walls, then the spheres
    int first_sphere = 5;
};

inline RainScene sphere_rain(int n, bool shifted = true) {
    using physics::BodyDef;
    using physics::Vec3;
    RainScene s;
    s.world.dt = 1.0 / 240.0;
    s.world.gravity = Vec3(0.0, 0.0, -9.81);
    s.world.contact.sleeping = false;
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

// What the end of a run is judged by (issue 4): the deepest overlap of any two shapes, how many
// spheres left the box (centre beyond a wall's inner face) or fell below the floor (centre under
// z = 0), and the kinetic energy sum 1/2 m |v|^2 + 1/2 w . I w (spheres: I = 2/5 m r^2).
struct RainEnd {
    double max_penetration = 0.0; // m
    int outside = 0;
    double kinetic_energy = 0.0; // J
};

inline RainEnd judge_rain(const RainScene& scene, const physics::State& s) {
    constexpr double r = 0.05, m = 0.1, wall = 2.0, cell = 2.0 * r;
    RainEnd e;
    const int first = scene.first_sphere, n = static_cast<int>(s.x.size());
    std::unordered_map<std::int64_t, std::vector<int>> grid; // spheres by cell of size 2r
    auto key = [](std::int64_t ix, std::int64_t iy, std::int64_t iz) {
        return (ix + (1 << 20)) << 42 | (iy + (1 << 20)) << 21 | (iz + (1 << 20));
    };
    auto cell_of = [&](double v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
    for (int i = first; i < n; ++i) {
        const physics::Vec3& x = s.x[i];
        e.outside += std::abs(x.x()) > wall || std::abs(x.y()) > wall || x.z() < 0.0;
        e.max_penetration = std::max({e.max_penetration, r - x.z(), x.x() + r - wall,
                                      -wall - (x.x() - r), x.y() + r - wall, -wall - (x.y() - r)});
        e.kinetic_energy +=
            0.5 * m * s.v[i].squaredNorm() + 0.5 * 0.4 * m * r * r * s.w[i].squaredNorm();
        grid[key(cell_of(x.x()), cell_of(x.y()), cell_of(x.z()))].push_back(i);
    }
    for (int i = first; i < n; ++i) {
        const physics::Vec3& x = s.x[i];
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

// FNV-1a over the bytes of every body's x, q, v, w (Box2D's test_determinism habit).
inline std::uint64_t state_hash(const physics::State& s) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
        mix(s.x[i].data(), sizeof(double) * 3);
        mix(s.q[i].coeffs().data(), sizeof(double) * 4);
        mix(s.v[i].data(), sizeof(double) * 3);
        mix(s.w[i].data(), sizeof(double) * 3);
    }
    return h;
}

} // namespace tumble::bench
