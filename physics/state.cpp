#include "physics/state.h"

#include "physics/model.h"

namespace tumble::physics {

double State::time(const Model& model) const {
    return static_cast<double>(step) * model.dt;
}

Pose body_pose(const Model& model, const State& state, int body) {
    const Quat orientation = state.q[body] * model.body_from_mass[body].conjugate();
    const Vec3 position = state.x[body] - orientation * model.com_offset[body];
    return {position, orientation};
}

} // namespace tumble::physics
