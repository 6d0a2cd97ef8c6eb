// The planner of "auto" (physics/accuracy_plan.h): deterministic, chooses for the whole duration,
// and its choice meets the tolerance against the exact Jacobi motion (physics/exact, which the
// planner never reads).
#include "physics/accuracy_plan.h"
#include "physics/build.h"
#include "physics/exact/body_motion.h"
#include "physics/scenes/reference_scenes.h"
#include "physics/step.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tumble::test {
namespace {

using namespace physics;

struct Start {
    Model model;
    State state;
};

Start book_flip() {
    const scenes::Scene s = scenes::intermediate_axis_scene();
    Model m = build_model(s.world, s.bodies);
    State st = initial_state(m, s.bodies);
    return {std::move(m), std::move(st)};
}

// Largest orientation error (rad) of a run against the exact motion, checked at every base step.
double true_error(const Start& s, const AccuracyPlan& plan, double base, std::int64_t frames) {
    Model m = s.model;
    m.integrator = plan.integrator;
    m.dt = plan.h;
    State st = s.state;
    const int body = m.dynamic_bodies.front();
    const exact::ExactBodyMotion oracle(s.model, s.state, body);
    double worst = 0.0;
    for (std::int64_t f = 1; f <= frames; ++f) {
        for (int i = 0; i < plan.k; ++i) step(m, st);
        const exact::BodyState ref = oracle.at(static_cast<double>(f) * base);
        worst = std::max(worst, st.q[body].angularDistance(ref.q));
        worst = std::max(worst, (st.x[body] - ref.x).norm());
    }
    return worst;
}

TEST(AccuracyPlan, SameSceneSamePlan) {
    const Start s = book_flip();
    const Tolerance tol{1e-4, 1e-4};
    const AccuracyPlan a = plan_accuracy(s.model, s.state, 1.0 / 60, 150, tol);
    const AccuracyPlan b = plan_accuracy(s.model, s.state, 1.0 / 60, 150, tol);
    ASSERT_TRUE(a.found);
    EXPECT_EQ(a.integrator, b.integrator);
    EXPECT_EQ(a.k, b.k);
    ASSERT_EQ(a.trials.size(), b.trials.size());
    for (std::size_t i = 0; i < a.trials.size(); ++i)
        EXPECT_EQ(a.trials[i].error, b.trials[i].error) << i; // bit for bit
}

// Near the separatrix an energy error becomes an error in the time of every flip: a plan for 2.5 s
// (one flip) is not good enough for 20 s (eight), and the planner, running the whole duration,
// buys more accuracy for the longer run. Both meet the tolerance against the exact motion. (The
// approximating integrators only: `exact` has no step error to grow.)
TEST(AccuracyPlan, ChoosesForTheWholeDuration) {
    const Start s = book_flip();
    const Tolerance tol{1e-4, 1e-4};
    const double base = 1.0 / 60;
    PlanSettings approximate;
    for (const IntegratorInfo& info : integrators())
        if (info.order > 0) approximate.only.push_back(info.id);
    const AccuracyPlan short_run = plan_accuracy(s.model, s.state, base, 150, tol, approximate);
    const AccuracyPlan long_run = plan_accuracy(s.model, s.state, base, 1200, tol, approximate);
    ASSERT_TRUE(short_run.found);
    ASSERT_TRUE(long_run.found);
    EXPECT_LE(true_error(s, short_run, base, 150), tol.rotation);
    EXPECT_LE(true_error(s, long_run, base, 1200), tol.rotation);
    // Per second of simulated time the long plan costs more (a finer step or a costlier method).
    EXPECT_GT(long_run.cost / 1200.0, short_run.cost / 150.0)
        << integrator_info(short_run.integrator).name << " k=" << short_run.k << " vs "
        << integrator_info(long_run.integrator).name << " k=" << long_run.k;
}

TEST(AccuracyPlan, TighterToleranceNeverCostsLess) {
    const Start s = book_flip();
    double last = 0.0;
    for (double tol : {1e-2, 1e-4, 1e-6}) {
        const AccuracyPlan p = plan_accuracy(s.model, s.state, 1.0 / 60, 150, Tolerance{tol, tol});
        ASSERT_TRUE(p.found) << tol;
        EXPECT_GE(p.cost, last) << tol;
        last = p.cost;
    }
}

} // namespace
} // namespace tumble::test
