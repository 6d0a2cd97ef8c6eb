// The error estimate (physics/error_estimate.h: step doubling with Richardson extrapolation)
// against the TRUE error: every study problem with an exact reference (the Jacobi elliptic
// solution of the torque-free body, the projectile, the sphere under a torque along its spin:
// physics/exact through app/study's make_reference) is run with every integrator of the registry
// at two steps in its asymptotic range, and at every sample time t_j = j T / 50 the true error of
// each body (angle of R_exact^T R, |x - x_exact|) is set against its estimate. At the end and for
// the maximum over the run, estimate / true must lie in [1/3, 3]. Where the true error is at
// round-off (an integrator exact for the motion: the translation of rk4, the splittings and
// midpoint under constant gravity; the splittings on an axisymmetric body), the estimate must be at
// round-off too.
//
// Measured on this VM (the same bits on any machine that rounds as IEEE says):
// Orientation, estimate / true at the end and for the max over the run (the body farthest from 1):
//   intermediate-axis euler            n   5000 0.999 0.999   n  10000 1.000 1.000
//                     euler_momentum   n   5000 0.998 0.998   n  10000 0.999 0.999
//                     symplectic_euler n   5000 0.999 0.999   n  10000 1.000 1.000
//                     implicit_gyro    n   5000 1.000 1.000   n  10000 1.000 1.000
//                     rk4              n    250 0.999 0.999   n    500 0.999 0.999
//                     splitting        n    500 1.000 1.000   n   1000 1.000 1.000
//                     midpoint         n    500 1.000 1.000   n   1000 1.000 1.000
//                     splitting4       n    250 1.000 1.000   n    500 1.002 1.001
//   largest-axis      euler            n   5000 1.035 1.027   n  10000 1.018 1.013
//                     euler_momentum   n   5000 1.017 1.017   n  10000 1.008 1.008
//                     symplectic_euler n   5000 1.010 1.008   n  10000 1.005 1.004
//                     implicit_gyro    n   5000 0.990 0.992   n  10000 0.995 0.996
//                     rk4              n    250 0.999 0.999   n    500 0.999 0.999
//                     splitting        n    500 1.000 1.000   n   1000 1.000 1.000
//                     midpoint         n    500 1.000 1.000   n   1000 1.000 1.000
//                     splitting4       n    250 1.000 1.000   n    500 1.000 1.000
//   axisymmetric      euler            n   5000 0.991 0.991   n  10000 0.996 0.996
//                     euler_momentum   n   5000 0.997 0.997   n  10000 0.999 0.999
//                     symplectic_euler n   5000 1.002 1.002   n  10000 1.001 1.001
//                     implicit_gyro    n   5000 0.998 0.998   n  10000 0.999 0.999
//                     rk4              n    250 1.000 1.000   n    500 1.000 1.000
//                     splitting        n    500 round-off (1e-14)   n   1000 round-off (9e-15)
//                     midpoint         n    500 1.000 1.000   n   1000 1.000 1.000
//                     splitting4       n    250 round-off (1e-14)   n    500 round-off (1e-14)
//   fast-spin         euler            n  10000 1.133 1.088   n  20000 1.069 1.044
//                     euler_momentum   n  10000 1.061 1.058   n  20000 1.030 1.029
//                     symplectic_euler n  10000 1.035 1.029   n  20000 1.018 1.014
//                     implicit_gyro    n  10000 0.966 0.971   n  20000 0.983 0.986
//                     rk4              n    500 0.999 0.999   n   1000 0.999 0.999
//                     splitting        n   1000 1.000 1.000   n   2000 1.000 1.000
//                     midpoint         n   1000 1.000 1.000   n   2000 1.000 1.000
//                     splitting4       n    500 1.000 1.000   n   1000 1.000 1.000
//   thin-rod          euler            n  50000 0.996 0.996   n 100000 0.998 0.998
//                     euler_momentum   n  50000 1.008 1.008   n 100000 1.004 1.004
//                     symplectic_euler n  50000 1.003 1.003   n 100000 1.001 1.001
//                     implicit_gyro    n  50000 0.997 0.997   n 100000 0.999 0.999
//                     rk4              n    500 1.000 1.000   n   1000 1.000 1.000
//                     splitting        n   1000 round-off (6e-14)   n   2000 round-off (7e-14)
//                     midpoint         n   1000 1.000 1.000   n   2000 1.000 1.000
//                     splitting4       n    500 round-off (8e-14)   n   1000 round-off (2e-13)
//   projectile-spin   euler            n    500 1.023 1.020   n   1000 1.012 1.010
//                     euler_momentum   n    500 1.009 1.009   n   1000 1.004 1.004
//                     symplectic_euler n    500 1.005 1.005   n   1000 1.002 1.002
//                     implicit_gyro    n    500 0.994 0.995   n   1000 0.997 0.997
//                     rk4              n    100 1.000 1.000   n    200 1.000 1.000
//                     splitting        n    200 1.000 1.000   n    400 1.000 1.000
//                     midpoint         n    200 1.000 1.000   n    400 1.000 1.000
//                     splitting4       n    100 1.000 1.000   n    200 1.000 1.000
// Position (centre of mass), where above round-off (projectile-spin; the order-1 methods):
//   projectile-spin   euler            n    500 1.000 1.000   n   1000 1.000 1.000
//   projectile-spin   euler_momentum   n    500 1.000 1.000   n   1000 1.000 1.000
//   projectile-spin   symplectic_euler n    500 1.000 1.000   n   1000 1.000 1.000
//   projectile-spin   implicit_gyro    n    500 1.000 1.000   n   1000 1.000 1.000
// Over the study's whole grid (OverTheStudysWholeGrid) it holds for every (body, orientation or
// position) whose true error lies in 1e-8 .. 1e-2: intermediate-axis 77 of 77, largest-axis 94 of
// 94, axisymmetric 66 of 66, fast-spin 80 of 80, thin-rod 35 of 35, projectile-spin 265 of 265.
// Outside the asymptotic range it need not (docs/error-estimate.md: implicit_gyro with
// h |w| = 0.5 on the fast spin underestimates 6.5x).
#include "app/study/metrics.h"
#include "app/study/study.h"
#include "physics/accuracy_plan.h"
#include "physics/error_estimate.h"
#include "physics/integrator.h"
#include "physics/step.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace tumble::test {
namespace {

namespace study = app::study;
using physics::Integrator;

// Below these the true error is round-off (measured: rk4's translation under gravity 2e-15 to
// 8e-13 m, the splittings on the axisymmetric top 1e-13 rad), and the estimate is held to the
// same floor instead of a ratio.
constexpr double kRoundOffRad = 1e-10, kRoundOffM = 1e-10;

// Step counts n (h = T / n, n a multiple of study::kSamples) in each integrator order's asymptotic
// range, chosen from the study's grid where the true error is above round-off and below 0.1 rad
// (tumble study: errors against h).
struct Steps {
    std::int64_t order1[2], order2[2], order4[2];
};
const std::map<std::string, Steps> kSteps = {
    {"intermediate-axis", {{5000, 10000}, {500, 1000}, {250, 500}}}, // T = 2.5 s
    {"largest-axis", {{5000, 10000}, {500, 1000}, {250, 500}}},      // T = 2.5 s
    {"axisymmetric", {{5000, 10000}, {500, 1000}, {250, 500}}},      // T = 2.5 s
    {"fast-spin", {{10000, 20000}, {1000, 2000}, {500, 1000}}},      // T = 0.05 s
    {"thin-rod", {{50000, 100000}, {1000, 2000}, {500, 1000}}},      // T = 2 s
    {"projectile-spin", {{500, 1000}, {200, 400}, {100, 200}}},      // T = 1 s
};

const std::int64_t* steps_for(const Steps& s, int order) {
    return order == 1 ? s.order1 : order == 2 ? s.order2 : s.order4;
}

struct Ratios {
    double end = 0.0, max = 0.0; // estimate / true
    double true_end = 0.0, true_max = 0.0;
    double est_end = 0.0, est_max = 0.0;
};

struct BodyRatios {
    int body = -1;
    Ratios rotation, position;
};

// One run with its estimate, against the reference at the sample times.
std::vector<BodyRatios> run(const study::Problem& p, const study::Reference& ref, Integrator id,
                            std::int64_t n) {
    study::Setup s = study::make_setup(p, id, p.duration / static_cast<double>(n));
    physics::ErrorEstimator e(s.model, s.state);
    std::vector<BodyRatios> out;
    for (const physics::BodyEstimate& b : e.bodies()) out.push_back({b.body, {}, {}});
    const std::int64_t per_sample = n / study::kSamples;
    for (std::int64_t k = 1; k <= n; ++k) {
        physics::step(s.model, s.state);
        e.advance(s.state);
        if (k % per_sample != 0) continue;
        const physics::State& exact = ref.states[std::size_t(k / per_sample)];
        for (std::size_t j = 0; j < out.size(); ++j) {
            const int i = out[j].body;
            const physics::BodyEstimate& b = e.bodies()[j];
            const double rot = physics::rotation_angle_between(exact.q[i], s.state.q[i]);
            const double pos = (exact.x[i] - s.state.x[i]).norm();
            Ratios& r = out[j].rotation;
            Ratios& x = out[j].position;
            r.true_max = std::max(r.true_max, rot), r.est_max = std::max(r.est_max, b.at.rotation);
            x.true_max = std::max(x.true_max, pos), x.est_max = std::max(x.est_max, b.at.position);
            r.true_end = rot, r.est_end = b.at.rotation;
            x.true_end = pos, x.est_end = b.at.position;
        }
    }
    for (BodyRatios& b : out)
        for (Ratios* r : {&b.rotation, &b.position}) {
            r->end = r->est_end / r->true_end;
            r->max = r->est_max / r->true_max;
        }
    return out;
}

// Within a factor of 3 where the true error is above round-off, else at round-off itself.
void check(const Ratios& r, double floor, const std::string& what) {
    if (r.true_max <= floor) {
        EXPECT_LE(r.est_max, 10 * floor) << what << ": true error at round-off (" << r.true_max
                                         << "), the estimate is not (" << r.est_max << ")";
        return;
    }
    EXPECT_GE(r.max, 1.0 / 3.0) << what << " (max over the run)";
    EXPECT_LE(r.max, 3.0) << what << " (max over the run)";
    if (r.true_end <= floor) return; // a zero crossing at the end: the max above is the check
    EXPECT_GE(r.end, 1.0 / 3.0) << what << " (at the end)";
    EXPECT_LE(r.end, 3.0) << what << " (at the end)";
}

class EstimateAgainstOracle : public ::testing::TestWithParam<std::string> {};

// `exact` refuses a problem with an applied torque (build_model, IntegratorsCli.ExactRefuses...):
// such a pair has no run to estimate.
bool refused(const study::Problem& p, physics::Integrator id) {
    const study::Setup s = study::make_setup(p, physics::Integrator::Rk4, p.duration / 50);
    return !physics::integrator_refusal(s.model, id).empty();
}

TEST_P(EstimateAgainstOracle, WithinAFactorOf3OfTheTrueError) {
    const auto& problems = study::problems();
    const auto it = std::find_if(problems.begin(), problems.end(),
                                 [](const study::Problem& p) { return p.name == GetParam(); });
    ASSERT_NE(it, problems.end());
    const study::Problem& p = *it;
    ASSERT_EQ(p.reference, study::ReferenceKind::Exact);
    const study::Reference ref = study::make_reference(p, false);
    double worst = 1.0; // the ratio farthest from 1 (in log) over every checked case
    for (const physics::IntegratorInfo& info : physics::integrators()) {
        if (refused(p, info.id)) continue;
        const std::int64_t* ns = steps_for(kSteps.at(p.name), info.order);
        for (int k = 0; k < 2; ++k) {
            for (const BodyRatios& b : run(p, ref, info.id, ns[k])) {
                const std::string what = p.name + " " + std::string(info.name) +
                                         " n = " + std::to_string(ns[k]) + " body " +
                                         std::to_string(b.body);
                std::printf("%-17s %-16s n = %6lld body %d  rot true %.2e est/true end %.3f max "
                            "%.3f | pos true %.2e end %.3f max %.3f\n",
                            p.name.c_str(), std::string(info.name).c_str(),
                            static_cast<long long>(ns[k]), b.body, b.rotation.true_max,
                            b.rotation.end, b.rotation.max, b.position.true_max, b.position.end,
                            b.position.max);
                check(b.rotation, kRoundOffRad, what + " orientation");
                check(b.position, kRoundOffM, what + " position");
                for (const Ratios* r : {&b.rotation, &b.position})
                    if (r->true_max > kRoundOffRad)
                        for (double q : {r->end, r->max})
                            if (std::isfinite(q) &&
                                std::abs(std::log(q)) > std::abs(std::log(worst)))
                                worst = q;
            }
        }
    }
    TUMBLE_MEASURED(worst, 3.0);
}

// Issue 17's criterion over the study's whole grid (5 steps per decade of h, every integrator): of
// the runs whose true error lies in the tolerances 1e-2 .. 1e-8 (rad or m), at least 95% have
// their estimate within a factor of 3 (end and max). Runs that diverge are left out.
TEST_P(EstimateAgainstOracle, OverTheStudysWholeGrid) {
    const auto& problems = study::problems();
    const study::Problem& p =
        *std::find_if(problems.begin(), problems.end(),
                      [](const study::Problem& q) { return q.name == GetParam(); });
    const study::Reference ref = study::make_reference(p, false);
    int cases = 0, within = 0;
    for (const physics::IntegratorInfo& info : physics::integrators()) {
        if (refused(p, info.id)) continue;
        for (std::int64_t n : study::step_counts(p, false)) {
            std::vector<BodyRatios> bodies;
            try {
                bodies = run(p, ref, info.id, n);
            } catch (const physics::DivergenceError&) {
                continue;
            }
            for (const BodyRatios& b : bodies)
                for (const Ratios* r : {&b.rotation, &b.position}) {
                    if (r->true_max < 1e-8 || r->true_max > 1e-2) continue;
                    ++cases;
                    const bool ok = r->max >= 1.0 / 3 && r->max <= 3 &&
                                    (r->true_end < 1e-10 || (r->end >= 1.0 / 3 && r->end <= 3));
                    within += ok;
                    if (!ok)
                        std::printf("outside: %s n = %lld body %d: end %.3f max %.3f\n",
                                    std::string(info.name).c_str(), static_cast<long long>(n),
                                    b.body, r->end, r->max);
                }
        }
    }
    const double fraction = cases > 0 ? double(within) / cases : 0.0;
    std::printf("%s: %d of %d runs within a factor of 3\n", p.name.c_str(), within, cases);
    TUMBLE_MEASURED(fraction, 0.95);
    EXPECT_GE(fraction, 0.95);
    EXPECT_GT(cases, 20); // measured: see the header
}

// Every study problem with an exact reference is covered (a new one needs its steps above).
TEST(EstimateAgainstOracle, CoversEveryExactProblem) {
    int exact = 0;
    for (const study::Problem& p : study::problems()) {
        if (p.reference != study::ReferenceKind::Exact) continue;
        ++exact;
        // The same book as intermediate-axis over 20 s: its whole grid would cost minutes here;
        // `tumble study --auto` checks the estimate on it (docs/accuracy.md).
        if (p.name == "intermediate-axis-20s") continue;
        EXPECT_TRUE(kSteps.count(p.name)) << p.name << " has no steps in this test";
    }
    EXPECT_EQ(exact, 7); // measured: 7 (six torque-free problems and projectile-spin)
}

INSTANTIATE_TEST_SUITE_P(Problems, EstimateAgainstOracle,
                         ::testing::Values("intermediate-axis", "largest-axis", "axisymmetric",
                                           "fast-spin", "thin-rod", "projectile-spin"),
                         [](const auto& info) {
                             std::string n = info.param;
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

} // namespace
} // namespace tumble::test
