#pragma once
// The "sphere rain" scene of issue 4, built in code so that every size N = n^3 is the same scene
// (the scene files assets/scenes/sphere_rain.json and sphere_columns.json are the case n = 10):
//   a 4 m x 4 m floor plane at z = 0 inside four static walls 1 m high at x = +-2 and y = +-2;
//   n^3 spheres of radius 0.05 m, mass 0.1 kg, friction 0.5, restitution 0.3, at rest on an
//   n x n x n grid with spacing 0.12 m centred over the floor, lowest layer at z = 0.5 m;
//   gravity 9.81 m/s^2 down; dt = 1/240 s; 5 s (1200 steps); sleeping off.
// Sphere i (ix = i mod n, iy = (i div n) mod n, iz = i div n^2) is shifted by 0.01 m u(i, 0) in x
// and 0.01 m u(i, 1) in y, u from the 32-bit hash below, so that the columns topple into a pile
// ("shifted"); with the shift off the spheres stack in columns.
// Walls: boxes 0.1 m thick whose inner faces are the lines x, y = +-2; the x walls run the full
// 4.2 m so that the corners close, the y walls fit between them (static shapes may not overlap).
// Used by the contact determinism test (pinned hash), the scene-file test and the benchmark.
#include "physics/scenes/scene.h"

#include <cstdint>

namespace tumble::scenes {

// Bodies: 0 the floor, 1..4 the walls, then the spheres from this index on.
inline constexpr int kRainFirstSphere = 5;

// u(i, k) in [-1, 1): h = i*2654435761 + k*0x9E3779B9; h ^= h>>16; h *= 0x85EBCA6B; h ^= h>>13;
// h *= 0xC2B2AE35; h ^= h>>16; u = h / 2^32 * 2 - 1 (all in 32-bit unsigned arithmetic).
double rain_hash(std::uint32_t i, std::uint32_t k);

// The scene with n^3 spheres; `shifted` false: the columns variant.
Scene sphere_rain(int n, bool shifted = true);

// What the end of a run is judged by (issue 4): the deepest overlap of any two shapes, how many
// spheres left the box (centre beyond a wall's inner face) or fell below the floor (centre under
// z = 0), and the kinetic energy sum 1/2 m |v|^2 + 1/2 w . I w (spheres: I = 2/5 m r^2).
struct RainEnd {
    double max_penetration = 0.0; // m
    int outside = 0;
    double kinetic_energy = 0.0; // J
};

// Judges a state of sphere_rain(n, ...) (any n, either variant).
RainEnd judge_rain(const physics::State& s);

} // namespace tumble::scenes
