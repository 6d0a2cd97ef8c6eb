// `tumble diff` exits as scripts expect, and a frame drawn twice gives the same pixels (what
// golden images rest on; the suites themselves: tests/app/suite_*_test.cpp).
#include "render/png_io.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

namespace tumble::test {
namespace {

const std::filesystem::path kGoldens = std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests/goldens";

TEST(Stills, RenderingTheSameFrameTwiceGivesIdenticalPixels) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_tumble(dir, "render --frame 90 --width 320 --height 180 -o a.png").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, "render --frame 90 --width 320 --height 180 -o b.png").exit_code, 0);
    EXPECT_EQ(render::read_png(dir / "a.png").rgb, render::read_png(dir / "b.png").rgb);
}

TEST(Diff, ExitCodesAndDiffImageForScripts) {
    const auto dir = scratch_dir();
    const auto g = kGoldens;
    CliResult r = run_tumble(dir, "diff '" + (g / "default_0000.png").string() + "' '" +
                                      (g / "default_0000.png").string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("identical"), std::string::npos) << r.out;
    r = run_tumble(dir, "diff '" + (g / "default_0000.png").string() + "' '" +
                            (g / "default_0150.png").string() + "' -o d.png");
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "d.png"));
    r = run_tumble(dir, "diff missing.png '" + (g / "default_0000.png").string() + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("missing.png"), std::string::npos) << r.err;
}

// --max-cluster bounds the largest cluster of touching differing pixels beside the count: a 3x3
// blob passes a count of 40 and fails a cluster bound of 4.
TEST(Diff, MaxClusterFailsABlobTheCountAllows) {
    const auto dir = scratch_dir();
    render::Image blob = render::read_png(kGoldens / "default_0000.png");
    for (int y = 40; y < 43; ++y)
        for (int x = 60; x < 63; ++x) {
            std::uint8_t* p = blob.row(y) + 3 * x;
            p[0] = 255, p[1] = 0, p[2] = 255;
        }
    render::write_png(dir / "blob.png", blob);
    const std::string args = "diff '" + (kGoldens / "default_0000.png").string() + "' blob.png";
    CliResult r = run_tumble(dir, args + " --max-different 40");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    r = run_tumble(dir, args + " --max-different 40 --max-cluster 4");
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.out.find("largest cluster 9 pixels (allowed 4) in the 3x3 box at (60, 40)"),
              std::string::npos)
        << r.out;
}

} // namespace
} // namespace tumble::test
