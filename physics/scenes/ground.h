#pragma once
// The ground: a static plane z = 0 (normal +z) that every contact scene stands on.
#include "physics/build.h"

namespace tumble::scenes {

// The static plane z = 0 with Coulomb friction `friction` (0.5 is the Material default).
physics::BodyDef ground(double friction = 0.5);

} // namespace tumble::scenes
