// Issue 30, item 6: a `tumble simulate` CSV records the scene it was made from, so that `tumble
// plot` draws a body's quantity that needs masses (w_body, its energy) without --scene; a scene
// file changed since is refused rather than drawn with other masses.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <sstream>

namespace tumble::test {
namespace {

TEST(PlotCli, ABodysQuantityNeedsNoSceneTheRunRecordsIt) {
    const auto dir = scratch_dir();
    const CliResult sim =
        run_tumble(dir, "simulate lessons/intermediate_axis --duration 1 -q -o runs/book.csv");
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    EXPECT_TRUE(read_text(dir / "runs/book.csv").starts_with("# tumble scene {\"content_hash\":\""))
        << read_text(dir / "runs/book.csv").substr(0, 200);
    const CliResult plot =
        run_tumble(dir, "plot runs/book.csv --quantity w_body --bodies book -q -o w.png");
    ASSERT_EQ(plot.exit_code, 0) << plot.err;
    // The same figure as with --scene: the same data.
    const CliResult named = run_tumble(dir, "plot runs/book.csv --quantity w_body --bodies book "
                                            "--scene lessons/intermediate_axis -q -o named.png");
    ASSERT_EQ(named.exit_code, 0) << named.err;
    EXPECT_EQ(read_text(dir / "w.dat"), read_text(dir / "named.dat"));

    // A scene file, then edited: the run's masses may no longer be the file's.
    const CliResult show =
        run_shell(dir, "\"$TUMBLE\" scenes --show lessons/intermediate_axis > book.json");
    ASSERT_EQ(show.exit_code, 0) << show.err;
    ASSERT_EQ(run_tumble(dir, "simulate book.json --duration 1 -q -o file.csv").exit_code, 0);
    ASSERT_EQ(
        run_tumble(dir, "plot file.csv --quantity w_body --bodies book -q -o f.png").exit_code, 0);
    std::string text = read_text(dir / "book.json");
    text.replace(text.find("\"mass\": 0.8"), 11, "\"mass\": 0.9");
    write_text(dir / "book.json", text);
    const CliResult changed =
        run_tumble(dir, "plot file.csv --quantity w_body --bodies book -q -o g.png");
    EXPECT_EQ(changed.exit_code, 2);
    EXPECT_NE(changed.err.find("has changed since"), std::string::npos) << changed.err;
    EXPECT_NE(changed.err.find("--scene"), std::string::npos) << changed.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "g.png"));
}

} // namespace
} // namespace tumble::test
