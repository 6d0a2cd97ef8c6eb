// `tumble simulate`: the trajectory CSV, bit-identical reruns, and a regression reference of the
// default scene's first second.
#include "support/cli_runner.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::test {
namespace {

// The rows of a CSV, header first, without its comments (a states table's first line records
// its scene: app/run/trajectory_rows.h).
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& p) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(read_text(p));
    std::string line;
    while (std::getline(in, line)) {
        if (line.starts_with("#")) continue;
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream ls(line);
        while (std::getline(ls, cell, ',')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

TEST(Simulate, WritesStatesAndDiagnosticsAtTheRequestedSteps) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "simulate --duration 0.5 --every 6 -o run/states.csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(files_in(dir),
              (std::vector<std::string>{"run/states.csv", "run/states.diagnostics.csv"}));
    const auto states = read_csv(dir / "run/states.csv");
    const auto diags = read_csv(dir / "run/states.diagnostics.csv");
    // 0.5 s at 60 fps and dt = 1/240 s is 120 steps, to t = 0.5 s; rows at 0, 6, .., 114, 120.
    ASSERT_EQ(diags.size(), 1u + 21u);
    EXPECT_EQ(diags.back()[0], "120");
    EXPECT_NEAR(std::stod(diags.back()[1]), 0.5, 1e-15);
    EXPECT_EQ(states.size(), 1u + 21u * 5u); // five bodies in the default scene
    EXPECT_EQ(states[0][0], "step");
    // Energy is conserved to rk4 accuracy until the first ball lands (the lowest starts 0.8 m
    // above the ground: t = sqrt(2 0.8 / 9.81) = 0.40 s), and bounces only ever lose energy.
    const double e0 = std::stod(diags[1][4]);
    double free_drift = 0.0, rise = 0.0, previous = e0;
    for (std::size_t r = 1; r < diags.size(); ++r) {
        const double t = std::stod(diags[r][1]), e = std::stod(diags[r][4]);
        if (t < 0.38) free_drift = std::max(free_drift, std::abs(e / e0 - 1.0));
        rise = std::max(rise, (e - previous) / std::abs(e0));
        previous = e;
    }
    TUMBLE_MEASURED(free_drift, 1e-8);
    EXPECT_LT(free_drift, 1e-8);
    TUMBLE_MEASURED(rise, 1e-9);
    EXPECT_LT(rise, 1e-9);
    EXPECT_LT(std::stod(diags.back()[4]), e0); // the balls have bounced
}

// The trajectory reaches t = duration, with or without --every, even where the scene's dt is
// lowered to fit the frames (dt 0.001 at 60 fps: 17 steps of 1/1020 s per frame).
TEST(Simulate, TheLastRowIsAtTheDuration) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", R"({"format_version": 1, "world": {"dt": 0.001, "duration": 2},
        "bodies": [{"name": "b", "shape": {"type": "sphere", "radius": 0.1}}]})");
    for (const char* every : {"1", "7"}) {
        SCOPED_TRACE(every);
        ASSERT_EQ(
            run_tumble(dir, std::string("simulate s.json -q -o s.csv --every ") + every).exit_code,
            0);
        const auto rows = read_csv(dir / "s.csv");
        EXPECT_EQ(rows.back()[0], std::to_string(2 * 60 * 17));
        EXPECT_NEAR(std::stod(rows.back()[1]), 2.0, 1e-12);
    }
}

TEST(Simulate, TwoRunsAreBitIdentical) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_tumble(dir, "simulate --duration 2 -o a.csv").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, "simulate --duration 2 -o b.csv").exit_code, 0);
    EXPECT_EQ(read_text(dir / "a.csv"), read_text(dir / "b.csv")); // %.17g: equal text = equal bits
    EXPECT_EQ(read_text(dir / "a.diagnostics.csv"), read_text(dir / "b.diagnostics.csv"));
}

// The default scene's first second, against tests/data/default_states.csv (regenerate on purpose
// with scripts/update-references.sh when the physics or the default scene changes on purpose).
// Tolerance: 1e-9 relative to the value's scale (or 1e-12 absolute), far above the run-to-run
// difference on one machine (zero) and far below any change of algorithm or scene.
TEST(Simulate, DefaultSceneMatchesCommittedReference) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_tumble(dir, "simulate --duration 1 --every 24 -o states.csv").exit_code, 0);
    const auto got = read_csv(dir / "states.csv");
    const auto want =
        read_csv(std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests/data/default_states.csv");
    ASSERT_EQ(got.size(), want.size());
    double worst = 0.0;
    for (std::size_t r = 0; r < got.size(); ++r) {
        ASSERT_EQ(got[r].size(), want[r].size());
        for (std::size_t c = 0; c < got[r].size(); ++c) {
            if (r == 0 || c == 3) {
                EXPECT_EQ(got[r][c], want[r][c]);
                continue;
            }
            const double a = std::stod(got[r][c]), b = std::stod(want[r][c]);
            const double err = std::abs(a - b) / std::max(1e-3, std::abs(b));
            worst = std::max(worst, err);
            EXPECT_LE(err, 1e-9) << "row " << r << " column " << want[0][c];
        }
    }
    std::printf("[measured] worst relative difference = %.3g (bound 1e-9)\n", worst);
}

} // namespace
} // namespace tumble::test
