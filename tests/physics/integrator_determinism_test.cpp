// Determinism for every integrator: two runs of the same model give bit-identical states, and a
// saved state (a plain copy) continues bit-identically. The scene mixes what the integrators
// branch on: gravity, an applied torque, an isotropic ball and anisotropic tumbling boxes (without
// the torque for `exact`, which refuses it).
#include "integrator_harness.h"

#include <gtest/gtest.h>

namespace tumble::physics {
namespace {

using testing::bit_equal;
using testing::make_world;
using testing::name_of;
using testing::run;
using testing::World;

scenes::Scene mixed_scene(Integrator id) {
    scenes::Scene scene = scenes::gravity_spin_scene();
    const scenes::Scene flip = scenes::intermediate_axis_scene();
    scene.bodies.push_back(flip.bodies[0]);
    scene.bodies.back().position = Vec3(2.0, 0.0, 1.0);
    return testing::as_taken_by(scene, id);
}

class IntegratorDeterminism : public ::testing::TestWithParam<Integrator> {};

TEST_P(IntegratorDeterminism, TwoRunsAreBitIdentical) {
    World a = make_world(mixed_scene(GetParam()), GetParam(), 1.0 / 240.0);
    World b = make_world(mixed_scene(GetParam()), GetParam(), 1.0 / 240.0);
    run(a, 1200);
    run(b, 1200);
    EXPECT_TRUE(bit_equal(a.state, b.state)) << name_of(GetParam());
}

TEST_P(IntegratorDeterminism, RestoredStateContinuesBitIdentically) {
    World w = make_world(mixed_scene(GetParam()), GetParam(), 1.0 / 240.0);
    run(w, 600);
    const State saved = w.state;
    run(w, 600);
    World resumed{w.model, saved};
    run(resumed, 600);
    EXPECT_TRUE(bit_equal(w.state, resumed.state)) << name_of(GetParam());
}

INSTANTIATE_TEST_SUITE_P(All, IntegratorDeterminism,
                         ::testing::ValuesIn(testing::all_integrators()),
                         [](const auto& param) { return name_of(param.param); });

} // namespace
} // namespace tumble::physics
