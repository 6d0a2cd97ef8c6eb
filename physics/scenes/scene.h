#pragma once
// A scene built in code: a world and its bodies as plain descriptions (physics/build.h), so that
// each caller builds it with its own integrator, step and thread count. Shared by the tests, the
// benchmarks and `tumble study` (tumble_scenes).
#include "physics/build.h"

#include <string>
#include <vector>

namespace tumble::scenes {

struct Scene {
    std::string name;
    physics::WorldDef world;
    std::vector<physics::BodyDef> bodies;
    double duration = 1.0; // s, a horizon over which the scene shows what it is for
};

} // namespace tumble::scenes
