#pragma once
// A fingerprint of a whole State, so that two runs can be compared bit for bit and a result
// pinned (the contact determinism test, the sphere-rain benchmark's 1 vs 2 threads).
#include "physics/state.h"

#include <cstdint>

namespace tumble::scenes {

// FNV-1a over the bytes of every body's x, q, v, w in body order (Box2D's test_determinism habit).
std::uint64_t state_hash(const physics::State& s);

} // namespace tumble::scenes
