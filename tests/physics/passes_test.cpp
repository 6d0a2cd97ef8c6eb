// "Model only what a scene requires": the assembled step (passes decided from the scene) and the
// full pipeline (force_all_passes: every pass on, no isotropic shortcut) give the same results.
//   - Skipping a load pass is bit-identical: the full pipeline adds exact zeros (m * 0 * g, a zero
//     applied force, I_w^-1 of a zero torque), and x + 0 == x bit for bit.
//   - Skipping an isotropic body's gyroscopic and inverse-inertia work agrees to round-off only:
//     w x I_w w and the body-frame round trip R (I^-1 (R^T tau)) are exact in exact arithmetic, but
//     the full pipeline evaluates them through two quaternion rotations whose rounding (~1e-16 per
//     step) the assembled step does not have. Over 2000 steps the two differ by 1e-15 to 4e-12
//     (euler_momentum on the torqued ball, which goes through I_w and I_w^-1 every step); the
//     bound, 1e-11, is 2000 steps of 5e-15, a few ulps of |w| each.
//   - The contact stage, forced on, finds no contact point in these scenes (no two shapes can
//     touch: physics/can_touch.h) and hands the whole step to the integrator: nothing changes.
//     Round-off agreement is only possible without collisions. When the torque-free spheres still
//     drifted into each other, spheres 10 and 13 met at step 1277 of 2000 (midpoint): a 1e-13
//     difference decided whether their speculative contact engaged at the end of that step or at
//     the start of the next, a 0.4 rad/s jump of w for one step and 1.3e-3 ever after
//     (implicit_gyro 1.3e-3, midpoint 4.7e-3, splitting4 similar; rk4, whose isotropic and full
//     paths agree to 1e-17, happened to fall on the same side). Substeps were not the cause: both
//     runs took the same two substeps. A collision is a discontinuous function of the state.
#include "integrator_harness.h"

#include "physics/passes.h"

#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace tumble::physics {
namespace {

using testing::bit_equal;
using testing::make_world;
using testing::name_of;
using testing::run;
using testing::World;

double max_difference(const Model& m, const State& a, const State& b) {
    double worst = 0.0;
    for (int i : m.dynamic_bodies)
        worst = std::max({worst, rotation_angle_between(a.q[i], b.q[i]),
                          (a.w[i] - b.w[i]).norm() / b.w[i].norm(), (a.x[i] - b.x[i]).norm(),
                          (a.v[i] - b.v[i]).norm()});
    return worst;
}

TEST(Passes, AssembledFromWhatTheSceneContains) {
    const World spheres = make_world(scenes::torque_free_spheres(10), Integrator::Rk4, 0.01);
    EXPECT_FALSE(spheres.model.passes.gravity);
    EXPECT_FALSE(spheres.model.passes.applied_loads);
    EXPECT_FALSE(spheres.model.passes.gyroscopic);
    EXPECT_FALSE(spheres.model.passes.contacts) << spheres.model.touch.why;
    const World mixed = make_world(scenes::gravity_spin_scene(), Integrator::Rk4, 0.01);
    EXPECT_TRUE(mixed.model.passes.gravity);
    EXPECT_TRUE(mixed.model.passes.applied_loads);
    EXPECT_TRUE(mixed.model.passes.gyroscopic);
    Model full = spheres.model;
    force_all_passes(full);
    EXPECT_TRUE(full.all_passes && full.passes.gravity && full.passes.applied_loads &&
                full.passes.gyroscopic && full.passes.contacts);
}

class PassesUnchanged : public ::testing::TestWithParam<Integrator> {};

TEST_P(PassesUnchanged, SkippedLoadPassesAreBitIdentical) {
    // The tumbling book without gravity or loads: full pipeline adds zeros, to the same bits.
    World assembled = make_world(scenes::intermediate_axis_scene(), GetParam(), 1.0 / 240.0);
    World full = assembled;
    force_all_passes(full.model);
    run(assembled, 2000);
    run(full, 2000);
    EXPECT_TRUE(bit_equal(assembled.state, full.state)) << name_of(GetParam());
}

TEST_P(PassesUnchanged, SkippedIsotropicWorkAgreesToRoundOff) {
    for (const scenes::Scene& scene :
         {scenes::torque_free_spheres(20), scenes::gravity_spin_scene()}) {
        World assembled =
            make_world(testing::as_taken_by(scene, GetParam()), GetParam(), 1.0 / 240.0);
        World full = assembled;
        force_all_passes(full.model);
        run(assembled, 2000);
        run(full, 2000);
        const double diff = max_difference(assembled.model, assembled.state, full.state);
        std::printf("[measured] %s, %s: assembled vs full %.3g\n", name_of(GetParam()).c_str(),
                    scene.name.c_str(), diff);
        TUMBLE_MEASURED(diff, 1e-11);
        EXPECT_LT(diff, 1e-11) << name_of(GetParam()) << " on " << scene.name;
    }
}

INSTANTIATE_TEST_SUITE_P(All, PassesUnchanged, ::testing::ValuesIn(testing::all_integrators()),
                         [](const auto& param) { return name_of(param.param); });

} // namespace
} // namespace tumble::physics
