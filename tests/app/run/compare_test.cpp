// `tumble render --compare`: integrators side by side. Each tile must be exactly the picture a
// plain render with that integrator draws at the tile's size, and the tiles must differ where
// the methods do.
#include "render/png_io.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <cstring>

namespace tumble::test {
namespace {

// A book spun about its middle axis with a coarse step, so that explicit Euler and RK4 part
// ways within a second; no ground, so nothing but the book moves.
const char* kScene = R"({
  "format_version": 1,
  "world": {"duration": 1, "dt": 0.025, "gravity": [0, 0, 0]},
  "render": {"fps": 20, "camera": {"position": [0, -2.5, 0.6], "target": [0, 0, 0]}},
  "bodies": [
    {"name": "book", "shape": {"type": "box", "size": [0.3, 0.2, 0.04]},
     "angular_velocity": [0.02, 8, 0.02], "color": "#c0392b"}
  ]
})";

// The w x h block of `image` whose top-left corner is (x0, y0).
render::Image crop(const render::Image& image, int x0, int y0, int w, int h) {
    render::Image out(w, h);
    for (int y = 0; y < h; ++y)
        std::memcpy(out.row(y), image.row(y0 + y) + 3 * x0, std::size_t(w) * 3);
    return out;
}

TEST(Compare, EachTileIsThePlainRenderOfItsIntegrator) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene);
    // 2 tiles of (322 - 2) / 2 = 160 x 96 pixels, side by side with a 2-pixel gutter.
    CliResult r = run_tumble(dir, "render s.json --compare euler,rk4 --width 322 --height 96 "
                                  "--frame 16 -o both.png -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* name : {"euler", "rk4"}) {
        r = run_tumble(dir, std::string("render s.json --integrator ") + name +
                                " --overlay --width 160 --height 96 --frame 16 -o " + name +
                                ".png -q");
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const render::Image both = render::read_png(dir / "both.png");
    ASSERT_EQ(both.width, 322);
    const render::Image left = crop(both, 0, 0, 160, 96), right = crop(both, 162, 0, 160, 96);
    EXPECT_TRUE(left.rgb == render::read_png(dir / "euler.png").rgb);
    EXPECT_TRUE(right.rgb == render::read_png(dir / "rk4.png").rgb);
    EXPECT_FALSE(left.rgb == right.rgb); // the methods have parted (and the labels differ)
}

// Without the overlay each tile still names its method (issue 14, item 6): a tile differs from
// the plain render only in its top-left corner, where the label is, and there it does.
TEST(Compare, TilesAreLabelledWithoutTheOverlay) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene);
    CliResult r = run_tumble(dir, "render s.json --compare euler,rk4 --no-overlay --width 322 "
                                  "--height 96 --frame 16 -o both.png -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const render::Image both = render::read_png(dir / "both.png");
    for (const auto& [name, x0] : {std::pair{"euler", 0}, std::pair{"rk4", 162}}) {
        r = run_tumble(dir, std::string("render s.json --no-overlay --integrator ") + name +
                                " --width 160 --height 96 --frame 16 -o plain.png -q");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const render::Image tile = crop(both, x0, 0, 160, 96);
        const render::Image plain = render::read_png(dir / "plain.png");
        int inside = 0, outside = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 160; ++x) {
                const bool differs = std::memcmp(tile.row(y) + 3 * x, plain.row(y) + 3 * x, 3);
                (x < 96 && y < 40 ? inside : outside) += differs;
            }
        EXPECT_GT(inside, 20) << name << ": no label";
        EXPECT_EQ(outside, 0) << name;
    }
}

TEST(Compare, WritesAVideoAndSummarisesEachMethod) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene);
    const CliResult r =
        run_tumble(dir, "render s.json --compare euler,symplectic_euler,rk4 --width 320 "
                        "--height 180 -o cmp.mp4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"cmp.mp4", "s.json"}));
    for (const char* name : {"euler:", "symplectic_euler:", "rk4:", "2 x 2 tiles"})
        EXPECT_NE(r.err.find(name), std::string::npos) << name << " missing in: " << r.err;
}

TEST(Compare, ADivergingMethodFreezesWhileTheOthersGoOn) {
    // h |w| = 0.2 s * 8 rad/s = 1.6: explicit Euler's energy grows each step until the angular
    // velocity overflows (step 43 measured); RK4 runs to the end.
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene);
    const CliResult r = run_tumble(dir, "render s.json --compare euler,rk4 --fps 5 --dt 0.2 "
                                        "--duration 10 --width 162 --height 48 -o d.mp4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("euler diverged: s.json: body 0"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("rk4: energy"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("wrote d.mp4 (50 frames"), std::string::npos) << r.err;
}

TEST(Compare, BadListsAreRefusedWithoutOutput) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene);
    for (const char* list : {"euler", "euler,nope", "rk4,rk4"}) {
        const CliResult r =
            run_tumble(dir, std::string("render s.json --compare ") + list + " -o x.mp4");
        EXPECT_EQ(r.exit_code, 2) << list;
        EXPECT_NE(r.err.find("--compare"), std::string::npos) << r.err;
    }
    const CliResult r = run_tumble(dir, "render s.json --compare euler,rk4 --integrator rk4");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"s.json"}));
}

} // namespace
} // namespace tumble::test
