// Accuracy as a setting: "auto" against the exact answers (the fast subset of `tumble study
// --auto`, app/study/auto_check.h). The true errors come from the study's references (the Jacobi
// oracles of physics/exact and closed forms), never from the planner or the estimate.
#include "app/study/auto_check.h"
#include "app/study/runner.h"
#include "app/study/study.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tumble::test {
namespace {

using namespace app::study;

std::vector<Problem> pick(const std::vector<std::string>& names) {
    std::vector<Problem> out;
    for (const Problem& p : problems())
        if (std::find(names.begin(), names.end(), p.name) != names.end()) out.push_back(p);
    return out;
}

// The grid's errors only (the cost check uses the planner's deterministic cost model): one
// repetition of the timing run.
std::vector<Row> quick_grid(const std::vector<Problem>& ps) {
    return run_grid(ps, true, 2, TimingSettings{1, 1e-5}, refused_pairs(ps), [](int, int) {});
}

TEST(AccuracyAuto, MeetsTheToleranceAtCloseToTheLeastCostAndKnowsItsError) {
    const std::vector<Problem> ps = pick({"intermediate-axis", "axisymmetric", "projectile-spin"});
    ASSERT_EQ(ps.size(), 3u);
    const std::vector<AutoCase> cases = check_auto(ps, quick_grid(ps), {1e-3, 1e-5, 1e-7}, true, 2);
    ASSERT_EQ(cases.size(), 9u);
    for (const AutoCase& c : cases) {
        SCOPED_TRACE(c.problem + " tolerance " + std::to_string(c.tolerance) + ": " + c.integrator +
                     " n=" + std::to_string(c.steps));
        ASSERT_TRUE(c.found);
        EXPECT_TRUE(c.covered); // free flight: the estimate holds throughout
        // The true error, against the oracle, within the tolerance.
        EXPECT_LE(c.truth, c.tolerance) << "estimate " << c.estimate;
        // The estimate within a factor of 3 of the true error.
        EXPECT_GE(c.ratio, 1.0 / 3.0) << "estimate " << c.estimate << " true " << c.truth;
        EXPECT_LE(c.ratio, 3.0) << "estimate " << c.estimate << " true " << c.truth;
        // At most 2x the cheapest grid row that met it (cost model; none met it: ratio 0).
        EXPECT_LE(c.cost_ratio_model, 2.0) << "cheapest " << c.cheapest;
    }
}

TEST(AccuracyAuto, ContactsAreReportedAsNotCovered) {
    const std::vector<Problem> ps = pick({"bouncing-ball"});
    ASSERT_EQ(ps.size(), 1u);
    const std::vector<AutoCase> cases = check_auto(ps, quick_grid(ps), {1e-3}, true, 1);
    ASSERT_EQ(cases.size(), 1u);
    // The ball lands at t = 0.452 s: its estimate stops holding there, and the case says so.
    EXPECT_FALSE(cases[0].covered);
    const AutoSummary s = summarise(cases);
    EXPECT_EQ(s.cases, 1);
    EXPECT_EQ(s.covered, 0);
}

} // namespace
} // namespace tumble::test
