#pragma once
// Physics' double-precision vectors as the renderer's single-precision ones: the one place the
// view narrows a pose for drawing (the state itself stays double).
#include "physics/math.h"

#include <glm/glm.hpp>

namespace tumble::app {

inline glm::vec3 to_glm(const physics::Vec3& v) {
    return {float(v.x()), float(v.y()), float(v.z())};
}

} // namespace tumble::app
