// Issue 30, item 5: README's examples show what they say, run as they are written there. The
// comparison of integrators shows each one's own energy drift (on the default scene the bounces'
// losses hid it: four equal curves); the drift figure is of a scene with no torque and no
// contacts (`tumble explain` says so); the GIF recipe draws the full look and the run says the
// frame rate the GIF plays at.
#include "support/cli_runner.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

namespace tumble::test {
namespace {

// README's `$T ...` command lines (without "$T " and their comments) that contain `what`.
std::vector<std::string> readme_lines(const std::string& what) {
    std::istringstream in(read_text(std::filesystem::path(TUMBLE_SOURCE_DIR) / "README.md"));
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) {
        if (!line.starts_with("$T ") || line.find(what) == std::string::npos) continue;
        line = line.substr(3, line.find(" #") == std::string::npos ? std::string::npos
                                                                   : line.find(" #") - 3);
        while (!line.empty() && line.back() == ' ') line.pop_back();
        out.push_back(line);
    }
    return out;
}

// The line without its output and size, which the test gives.
std::string without_output(std::string line) {
    return std::regex_replace(line, std::regex(R"( (-o|--width|--height) \S+)"), "");
}

TEST(Readme, TheComparisonShowsEachIntegratorsOwnDrift) {
    const std::vector<std::string> lines = readme_lines("--compare");
    ASSERT_EQ(lines.size(), 1u);
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, without_output(lines[0]) +
                                            " --time 3 --width 640 --height 360 -o still.png");
    ASSERT_EQ(r.exit_code, 0) << lines[0] << r.err;
    // "tumble: rk4: energy 0.111 J -> 0.111 J", one line per tile.
    std::vector<double> drifts;
    const std::regex energy(R"(tumble: \w+: energy (\S+) J -> (\S+) J)");
    for (std::sregex_iterator it(r.err.begin(), r.err.end(), energy), end; it != end; ++it) {
        const double e0 = std::stod((*it)[1]), e1 = std::stod((*it)[2]);
        drifts.push_back(std::abs(e1 - e0) / std::abs(e0));
    }
    ASSERT_GE(drifts.size(), 2u) << r.err;
    const double largest = *std::max_element(drifts.begin(), drifts.end());
    const double smallest = std::max(*std::min_element(drifts.begin(), drifts.end()), 1e-16);
    TUMBLE_MEASURED(largest / smallest, 100.0);
    EXPECT_GT(largest / smallest, 100.0) << "the tiles' drifts do not differ: " << r.err;
}

TEST(Readme, TheDriftFigureIsOfAFreeScene) {
    const std::vector<std::string> plots = readme_lines("--quantity energy_drift");
    ASSERT_EQ(plots.size(), 1u);
    // The runs it plots are made by README's simulate lines that write them.
    const auto dir = scratch_dir();
    std::istringstream words(plots[0]);
    int runs = 0;
    for (std::string word; words >> word;) {
        if (!word.ends_with(".csv")) continue;
        const std::vector<std::string> makers = readme_lines("-o " + word);
        ASSERT_EQ(makers.size(), 1u) << "no simulate line writes " << word;
        ASSERT_TRUE(makers[0].starts_with("simulate ")) << makers[0];
        std::istringstream m(makers[0]);
        std::string command, scene;
        m >> command >> scene;
        const CliResult explain = run_tumble(dir, "explain " + scene);
        ASSERT_EQ(explain.exit_code, 0) << explain.err;
        EXPECT_TRUE(std::regex_search(explain.out, std::regex(R"(contacts\s+off)"))) << explain.out;
        EXPECT_TRUE(std::regex_search(explain.out, std::regex(R"(applied loads\s+off)")))
            << explain.out;
        ++runs;
    }
    EXPECT_GE(runs, 2) << "the drift figure should compare integrators: " << plots[0];
}

TEST(Readme, TheGifRecipeDrawsTheFullLookAndSaysItsFrameRate) {
    const std::vector<std::string> gifs = readme_lines(".gif");
    ASSERT_EQ(gifs.size(), 1u);
    EXPECT_EQ(gifs[0].find("--preview"), std::string::npos) << gifs[0];
    const auto dir = scratch_dir();
    // Half a second of it, small.
    const CliResult r = run_tumble(dir, without_output(gifs[0]) +
                                            " --duration 0.5 --width 160 --height 90 -o a.gif");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("a.gif plays at 30 fps, every 2nd frame of 60 fps"), std::string::npos)
        << r.err;
    const CliResult fifty = run_tumble(dir, without_output(gifs[0]) +
                                                " --duration 0.5 --width 160 --height 90 --fps 50 "
                                                "-o b.gif");
    ASSERT_EQ(fifty.exit_code, 0) << fifty.err;
    EXPECT_EQ(fifty.err.find("plays at"), std::string::npos) << fifty.err;
}

} // namespace
} // namespace tumble::test
