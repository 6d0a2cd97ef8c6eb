// Every integrator run at h, 2h and 4h (Jolt's habit) on the gravity-and-spin scene: a book thrown
// up while turning about its largest axis and a ball spun up by a torque parallel to its spin,
// under g = 9.81 m/s^2, against the exact projectile, Jacobi and constant-torque solutions at
// t = 1 s. The error must scale as the method's order p: e(2h) / e(h) and e(4h) / e(2h) within a
// factor 1.25 of 2^p either way, and the error at h must stay under a stated accuracy budget.
#include "integrator_harness.h"

#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::physics {
namespace {

using testing::error_at_end;
using testing::name_of;

struct Ladder {
    double h;      // finest step
    double budget; // error allowed at h (rad + relative + m + m/s, see the harness)
};

// The finest step of each ladder and its budget: first-order methods at 1/960 s within 2e-2,
// second-order at 1/240 s (the default dt) within 5e-4, fourth-order at 1/120 s within 1e-6.
// Measured: euler 1.3e-2, euler_momentum 1.1e-2, symplectic_euler 7.9e-3, implicit_gyro 7.6e-3,
// splitting 1.3e-5, midpoint 2.3e-4, rk4 3.3e-7, splitting4 1.8e-9.
Ladder ladder(int order) {
    if (order == 1) return {1.0 / 960.0, 2e-2};
    if (order == 2) return {1.0 / 240.0, 5e-4};
    return {1.0 / 120.0, 1e-6};
}

class IntegratorScaling : public ::testing::TestWithParam<Integrator> {};

// The methods on the exact free flow. `exact` refuses the ball's torque. The exact-flow
// splittings are exact on this scene: the book is torque-free, and the ball is isotropic with its
// torque parallel to its spin, so the kicks (w += h/2 tau / I, along w) commute with the free flow
// (q <- exp(h w) q) and kick, flow, kick is the exact exp(h w + h^2 tau / (2 I)); the translation
// x + h v + h^2/2 g is exact under constant gravity. All three errors must be round-off (measured
// at h = 1/240, 1/120, 1/60 s: 1.0e-13, 2.1e-14, 3.5e-14 for splitting_exact; 2.5e-13, 2.7e-13,
// 4.4e-14 for splitting4_exact).
// Their order under a torque that does not commute: exact_integrator_test.cpp.
void expect_exact_or_refused(const IntegratorInfo& info, const scenes::Scene& scene) {
    if (info.refuses_torque) {
        try {
            error_at_end(scene, info.id, 1.0 / 240.0);
            ADD_FAILURE() << name_of(info.id) << " took a scene with an applied torque";
        } catch (const ModelError& e) {
            EXPECT_EQ(e.body, 1); // the ball
            EXPECT_EQ(e.field, "torque");
        }
        return;
    }
    for (double h : {1.0 / 240.0, 1.0 / 120.0, 1.0 / 60.0}) {
        const double e = error_at_end(scene, info.id, h);
        TUMBLE_MEASURED(e, 1e-12);
        EXPECT_LT(e, 1e-12) << name_of(info.id) << " at h = " << h;
    }
}

TEST_P(IntegratorScaling, ErrorScalesWithStepOnGravityAndSpin) {
    const IntegratorInfo& info = integrator_info(GetParam());
    const scenes::Scene scene = scenes::gravity_spin_scene();
    if (info.exact_without_torque) return expect_exact_or_refused(info, scene);
    const Ladder l = ladder(info.order);
    const double e1 = error_at_end(scene, info.id, l.h);
    const double e2 = error_at_end(scene, info.id, 2.0 * l.h);
    const double e4 = error_at_end(scene, info.id, 4.0 * l.h);
    const double expected = std::pow(2.0, info.order);
    const double r21 = e2 / e1, r42 = e4 / e2;
    std::printf("[measured] %s: errors %.3e %.3e %.3e at h = 1/%.0f, 2h, 4h; ratios %.3f %.3f "
                "(expected %.0f)\n",
                name_of(info.id).c_str(), e1, e2, e4, 1.0 / l.h, r21, r42, expected);
    TUMBLE_MEASURED(e1, l.budget);
    EXPECT_LT(e1, l.budget) << name_of(info.id);
    for (double r : {r21, r42}) {
        EXPECT_GT(r, expected / 1.25) << name_of(info.id);
        EXPECT_LT(r, expected * 1.25) << name_of(info.id);
    }
}

INSTANTIATE_TEST_SUITE_P(All, IntegratorScaling, ::testing::ValuesIn(testing::all_integrators()),
                         [](const auto& param) { return name_of(param.param); });

} // namespace
} // namespace tumble::physics
