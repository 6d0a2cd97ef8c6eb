// --error-estimate and world.error_estimate through the real binary: the run summary, the
// diagnostics CSV's columns, the overlay of a render, `tumble explain`, and bad input (the option
// or the JSON path named, with what was expected). The estimate's accuracy is measured in
// tests/physics/error_estimate_test.cpp and tests/app/study/error_estimate_oracle_test.cpp; here
// the numbers are checked against closed forms and a converged run.
#include "support/cli_runner.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace tumble::test {
namespace {

// A ball dropped 1 m onto the ground beside a book spinning about its largest axis high above it
// (no gravity on the book), both stepped by symplectic Euler at h = 1/240 s.
const char* kScene = R"({"format_version": 1,
  "world": {"duration": 2, "dt": 0.004166666666666667, "integrator": "symplectic_euler"%s},
  "bodies": [
    {"name": "ground", "shape": {"type": "plane"}},
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "mass": 1,
     "position": [0, 0, 1.1], "material": {"restitution": 0.8}},
    {"name": "book", "shape": {"type": "box", "size": [0.22, 0.05, 0.30]}, "mass": 0.8,
     "position": [3, 0, 20], "gravity_scale": 0, "angular_velocity": [0.2, 8, 0.3]}]})";

std::string scene_with(const std::string& world_extra) {
    char buffer[2048];
    std::snprintf(buffer, sizeof buffer, kScene, world_extra.c_str());
    return buffer;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t at = 0;
    for (;;) {
        const std::size_t comma = line.find(',', at);
        cells.push_back(line.substr(at, comma == std::string::npos ? comma : comma - at));
        if (comma == std::string::npos) return cells;
        at = comma + 1;
    }
}

// Rows of a CSV as maps from the header's names.
std::vector<std::map<std::string, std::string>> read_table(const std::filesystem::path& p) {
    std::istringstream in(read_text(p));
    std::string line;
    while (std::getline(in, line) && line.starts_with("#")) { // a states table's scene record
    }
    const std::vector<std::string> header = split(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = split(line);
        EXPECT_EQ(cells.size(), header.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i)
            row[header[i]] = cells[i];
        rows.push_back(row);
    }
    return rows;
}

// The ball's first contact: the start of the first step whose gap 1 - g h^2 n (n + 1) / 2
// (symplectic Euler's free fall) is within the speculative margin 1 cm + h g h n.
double first_contact(double h) {
    int n = 0;
    while (1.0 - 9.81 * h * h * n * (n + 1) / 2 > 0.01 + h * 9.81 * h * n) ++n;
    return n * h;
}

TEST(ErrorEstimateCli, SimulateSummaryAndDiagnosticsColumns) {
    const auto dir = scratch_dir();
    write_text(dir / "drop.json", scene_with(R"(, "error_estimate": {"times": [0.25, 1]})"));
    const CliResult r = run_tumble(dir, "simulate drop.json -o run.csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The summary: the method, every moving body at the end, at each chosen time and its maximum,
    // and where the ball's estimate stopped.
    EXPECT_NE(r.err.find("error estimate (step doubling"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("symplectic_euler of order 1, e = (y_h - y_h/2) x 2"), std::string::npos)
        << r.err;
    char stop[96];
    std::snprintf(stop, sizeof stop, "\"ball\": does not hold after t = %.6g s (contact)",
                  first_contact(1.0 / 240));
    EXPECT_NE(r.err.find(stop), std::string::npos) << stop << "\n" << r.err;
    EXPECT_NE(r.err.find("\"book\": end t = 2 s: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("; t = 0.25 s: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("; t = 1 s: does not hold; max "), std::string::npos) << r.err;
    // The diagnostics: two columns per moving body (the ground, body 0, has none); the ball's
    // position estimate is symplectic Euler's free-fall error g h t / 2 until its first contact,
    // then empty.
    const auto rows = read_table(dir / "run.diagnostics.csv");
    ASSERT_EQ(rows.size(), 481u);
    for (const char* column : {"err_rad_1", "err_m_1", "err_rad_2", "err_m_2"})
        EXPECT_EQ(rows[0].count(column), 1u) << column;
    EXPECT_EQ(rows[0].count("err_m_0"), 0u);
    double worst = 0.0;
    for (const auto& row : rows) {
        const double t = std::stod(row.at("t"));
        if (t > first_contact(1.0 / 240) + 1e-9) {
            EXPECT_EQ(row.at("err_m_1"), "") << t;
            continue;
        }
        if (t == 0.0) continue;
        const double expected = 9.81 * (1.0 / 240) * t / 2;
        worst = std::max(worst, std::abs(std::stod(row.at("err_m_1")) / expected - 1));
    }
    TUMBLE_MEASURED(worst, 1e-9); // measured 4.5e-12
    EXPECT_LT(worst, 1e-9);
    // The book holds throughout: a value in every row, growing from 0.
    EXPECT_EQ(rows.front().at("err_rad_2"), "0");
    EXPECT_GT(std::stod(rows.back().at("err_rad_2")), 0.0);
}

// The book's estimate at the end, as the summary prints it, against its true error: the same
// scene run converged (rk4 at h / 20; its own error is below 1e-9 rad) gives the book's exact
// orientation at t = 2 s.
TEST(ErrorEstimateCli, TheSummaryMatchesTheTrueErrorOfAConvergedRun) {
    const auto dir = scratch_dir();
    write_text(dir / "drop.json", scene_with(""));
    const CliResult run = run_tumble(dir, "simulate drop.json --error-estimate -o run.csv");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const CliResult ref =
        run_tumble(dir, "simulate drop.json --integrator rk4 --dt 0.000208333333333333 -o ref.csv");
    ASSERT_EQ(ref.exit_code, 0) << ref.err;
    const std::string key = "\"book\": end t = 2 s: ";
    const std::size_t at = run.err.find(key);
    ASSERT_NE(at, std::string::npos) << run.err;
    const double estimate = std::stod(run.err.substr(at + key.size()));
    auto last_book = [&](const char* file) {
        const auto rows = read_table(dir / file);
        for (auto it = rows.rbegin(); it != rows.rend(); ++it)
            if (it->at("name") == "\"book\"") return *it;
        return rows.back();
    };
    const auto a = last_book("run.csv"), b = last_book("ref.csv");
    double dot = 0.0;
    for (const char* k : {"qw", "qx", "qy", "qz"}) dot += std::stod(a.at(k)) * std::stod(b.at(k));
    const double truth = 2.0 * std::acos(std::min(1.0, std::abs(dot)));
    const double ratio = estimate / truth;
    TUMBLE_MEASURED(ratio, 3.0); // measured 1.06 (estimate 0.0074 rad, true error 0.0070 rad)
    EXPECT_GT(ratio, 1.0 / 3);
    EXPECT_LT(ratio, 3.0);
}

TEST(ErrorEstimateCli, RenderPrintsItAndExplainMentionsIt) {
    const auto dir = scratch_dir();
    write_text(dir / "drop.json", scene_with(R"(, "error_estimate": true)"));
    const CliResult r = run_tumble(dir, "render drop.json --frame 30 --preview --overlay -o f.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("\"book\": end t = 0.5 s: "), std::string::npos) << r.err;
    const CliResult off = run_tumble(dir, "render drop.json --frame 30 --preview "
                                          "--no-error-estimate -o g.png");
    ASSERT_EQ(off.exit_code, 0) << off.err;
    EXPECT_EQ(off.err.find("error estimate"), std::string::npos) << off.err;
    const CliResult e = run_tumble(dir, "explain drop.json");
    ASSERT_EQ(e.exit_code, 0) << e.err;
    EXPECT_NE(e.out.find("error estimate: on: step doubling"), std::string::npos) << e.out;
    write_text(dir / "plain.json", scene_with(""));
    const CliResult plain = run_tumble(dir, "explain plain.json");
    EXPECT_EQ(plain.out.find("error estimate"), std::string::npos) << plain.out;
}

// `tumble plot` reads a diagnostics table with the estimate's columns.
TEST(ErrorEstimateCli, PlotReadsDiagnosticsWithEstimateColumns) {
    const auto dir = scratch_dir();
    write_text(dir / "drop.json", scene_with(""));
    ASSERT_EQ(run_tumble(dir, "simulate drop.json --error-estimate -q -o run.csv").exit_code, 0);
    const CliResult r = run_tumble(dir, "plot run.diagnostics.csv --quantity energy -o e.svg");
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(ErrorEstimateCli, BadOptionValuesNameTheOptionAndWhatWasExpected) {
    const auto dir = scratch_dir();
    const struct {
        const char* args;
        const char* message;
    } cases[] = {
        {"--error-estimate=abc", "--error-estimate=abc: expected nothing, or =T1,T2,...: times in "
                                 "seconds >= 0 separated by commas"},
        {"--error-estimate=1,,2", "got an empty time"},
        {"--error-estimate=-1", "got \"-1\""},
        {"--error-estimate=inf", "got \"inf\""},
        {"--error-estimate=11", "--error-estimate=11: t = 11 s is after the end of the run (10 s)"},
        {"--error-estimate=3 --duration 2",
         "t = 3 s is after the end of the run (2 s, --duration)"},
        {"--error-estimate --no-error-estimate",
         "--error-estimate and --no-error-estimate: give one or the other"},
    };
    for (const auto& c : cases) {
        const CliResult r = run_tumble(dir, std::string("simulate -o x.csv ") + c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    }
}

// A render continued from a checkpoint has no shadow run to continue: refused before any output
// (exit 2); from t = 0 (--frames alone) the estimate is made as for the whole run.
TEST(ErrorEstimateCli, ACheckpointHasNoShadowToContinue) {
    const auto dir = scratch_dir();
    write_text(dir / "drop.json", scene_with(""));
    ASSERT_EQ(
        run_tumble(dir, "simulate drop.json --checkpoint-every 30 --checkpoints ck -q").exit_code,
        0);
    const std::string render = "render drop.json --preview --frames 60:70 -o part/ ";
    const CliResult r = run_tumble(dir, render + "--from-checkpoints ck --error-estimate");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--from-checkpoints: the error estimate"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "part"));
    const CliResult whole = run_tumble(dir, render + "--error-estimate");
    EXPECT_EQ(whole.exit_code, 0) << whole.err;
    EXPECT_NE(whole.err.find("\"book\": end t = 1.15 s: "), std::string::npos) << whole.err;
}

TEST(ErrorEstimateCli, SceneFieldErrorsNameTheJsonPath) {
    const auto dir = scratch_dir();
    const struct {
        const char* world;
        const char* extra; // option
        const char* message;
    } cases[] = {
        {R"(, "error_estimate": "yes")", "",
         "/world/error_estimate: expected true, false or {\"times\": [t1, t2, ...]}, got \"yes\""},
        {R"(, "error_estimate": {"times": [1, 5]})", "",
         "/world/error_estimate/times/1: expected a time within the duration (2 s), got 5 s"},
        {R"(, "error_estimate": {"times": [-1]})", "", "/world/error_estimate/times/0: expected"},
        {R"(, "error_estimate": {})", "",
         "/world/error_estimate: missing required field \"times\""},
        {R"(, "error_estimate": {"times": [1], "every": 2})", "", "/world/error_estimate"},
        {R"(, "error_estimate": {"times": [0.5, 1.5]})", "--duration 1",
         "/world/error_estimate/times/1: t = 1.5 s is after the end of the run (1 s, --duration)"},
    };
    for (const auto& c : cases) {
        write_text(dir / "bad.json", scene_with(c.world));
        const CliResult r = run_tumble(dir, std::string("simulate bad.json -o x.csv ") + c.extra);
        EXPECT_EQ(r.exit_code, 2) << c.world;
        EXPECT_NE(r.err.find(std::string("bad.json: ") + c.message), std::string::npos)
            << c.world << ": " << r.err;
    }
}

} // namespace
} // namespace tumble::test
