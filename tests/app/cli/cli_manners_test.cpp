// What a user meets at the command line (issue 14): default output names, notes about the step,
// summaries that count right, and mistakes answered as errors with a guess.
#include "app/scene/scene.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace tumble::test {
namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(CliManners, DefaultOutputsAreNamedForTheSceneNotItsSource) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_tumble(dir, "render --duration 0.05 --width 64 --height 48 -q").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, "render --frame 2 --width 64 --height 48 -q").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, "render --compare euler,rk4 --duration 0.05 --width 132 "
                              "--height 48 -q")
                  .exit_code,
              0);
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"default-compare.mp4", "default.mp4",
                                                       "default_000002.png"}));
}

TEST(CliManners, SimulateSaysWhenItLowersTheStep) {
    const auto dir = scratch_dir();
    // 1/60 s per frame over dt = 0.001 s needs ceil(16.67) = 17 steps of 1/(60 * 17) s.
    char lowered[96];
    std::snprintf(lowered, sizeof lowered, "dt 0.001 s lowered to %.9g s so that 17 steps",
                  1.0 / (60.0 * 17.0));
    CliResult r = run_tumble(dir, "simulate --dt 0.001 --duration 0.05 -o s.csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.err, std::string("tumble: note: ") + lowered)) << r.err;
    // dt = 1/240 s fits 4 steps to a frame exactly: nothing to say.
    r = run_tumble(dir, "simulate --dt 0.004166666666666667 --duration 0.05 -o s.csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(contains(r.err, "lowered")) << r.err;
}

TEST(CliManners, AStillsSummaryCountsOneFrameAtItsTime) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "render --frame 3 --width 64 --height 48 -o one.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.err, "frame 3 at t = 0.05 s")) << r.err; // 3 / 60 fps
    EXPECT_TRUE(contains(r.err, "tumble: 1 frame in ")) << r.err;
    EXPECT_FALSE(contains(r.err, "600 frames")) << r.err;
}

TEST(CliManners, NoCommandIsAnErrorWithTheUsageOnStderr) {
    const CliResult r = run_tumble(scratch_dir(), "");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(contains(r.err, "Subcommands:")) << r.err;
    EXPECT_TRUE(contains(r.err, "tumble: error: no command given")) << r.err;
}

TEST(CliManners, MistypedCommandsAndOptionsGetAGuess) {
    const auto dir = scratch_dir();
    CliResult r = run_tumble(dir, "rendr");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "tumble: error: ")) << r.err;
    EXPECT_TRUE(contains(r.err, "did you mean \"render\"")) << r.err;
    r = run_tumble(dir, "render --fsp 30");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "did you mean \"--fps\"")) << r.err;
    EXPECT_TRUE(contains(r.err, "tumble render --help")) << r.err;
    EXPECT_EQ(files_in(dir), std::vector<std::string>{}); // nothing rendered
}

TEST(CliManners, DiffHelpShowsItsDefaults) {
    const CliResult r = run_tumble(scratch_dir(), "diff --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_FALSE(contains(r.out, "{false}")) << r.out;
    EXPECT_TRUE(contains(r.out, "--max-different INT=0")) << r.out;
    EXPECT_TRUE(contains(r.out, "--no-aa")) << r.out;
}

// A plane without a colour is the floor: neutral grey, whatever its index in the palette.
TEST(CliManners, APlaneWithoutAColourIsNeutral) {
    const app::Scene s = app::load_scene(R"({"format_version": 1, "bodies": [
        {"shape": {"type": "plane"}},
        {"shape": {"type": "sphere", "radius": 0.1}, "position": [0, 0, 1]}]})",
                                         "plane.json");
    const glm::vec3 g = s.looks[0].color;
    const float spread = std::max({g.r, g.g, g.b}) - std::min({g.r, g.g, g.b});
    EXPECT_LT(spread, 0.05f) << g.r << " " << g.g << " " << g.b; // no hue
    EXPECT_GT(g.r, 0.5f);                                        // light
    EXPECT_NE(s.looks[1].color, g);
}

} // namespace
} // namespace tumble::test
