// `tumble diff` exits as scripts expect, and a frame drawn twice gives the same pixels (what
// golden images rest on; the suites themselves: tests/app/suite_*_test.cpp).
#include "app/cli_runner.h"
#include "render/png_io.h"

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

} // namespace
} // namespace tumble::test
