// `tumble sweep` as a user runs it: a bad --set writes nothing (exit 2), and the scenes of a
// sweep render.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

namespace tumble::test {
namespace {

TEST(SweepCli, ABadSetWritesNothingAndASweepSceneRenders) {
    const auto dir = scratch_dir();
    const CliResult bad = run_tumble(dir, "sweep default --set world.integrater=euler -o s/");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("did you mean \"integrator\""), std::string::npos) << bad.err;
    EXPECT_TRUE(files_in(dir).empty());
    const CliResult ok = run_tumble(
        dir, "sweep default --set world.integrator=euler,rk4 --set world.duration=0.1 -o s/");
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_EQ(files_in(dir / "s"),
              (std::vector<std::string>{"manifest.json", "scene_000.json", "scene_001.json"}));
    const CliResult render =
        run_tumble(dir, "render s/scene_000.json --width 160 --height 90 -o s.mp4");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_NE(render.err.find("integrator euler"), std::string::npos) << render.err;
}

} // namespace
} // namespace tumble::test
