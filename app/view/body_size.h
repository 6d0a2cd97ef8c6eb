#pragma once
// How big a body looks, for sizing what is drawn beside it (arrows, trails' axis tips, Poinsot's
// ellipsoid): 1.7 sqrt(I_max / m), about its radius for a sphere (sqrt(0.4) r x 1.7 = 1.08 r)
// and its half-diagonal for a box. From the inertia, so it needs no shape.
#include "physics/model.h"

#include <cmath>

namespace tumble::app {

inline double body_size(const physics::Model& model, int body) {
    const std::size_t b = std::size_t(body);
    return 1.7 * std::sqrt(model.inertia[b].maxCoeff() / model.mass[b]);
}

} // namespace tumble::app
