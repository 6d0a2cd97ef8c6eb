// Issue 30, item 4: `render --camera POSITION:TARGET[:FOV]` moves the camera from the command
// line (checked against the same camera written into a scene file), and `tumble scenes --show
// NAME` prints a built-in scene's JSON to start from (checked against the file it is built from).
#include "render/png_io.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace tumble::test {
namespace {

std::string source_file(const std::string& relative) {
    return read_text(std::filesystem::path(TUMBLE_SOURCE_DIR) / relative);
}

TEST(RenderCli, CameraOptionPlacesTheCameraAsASceneFileWould) {
    const auto dir = scratch_dir();
    const std::string size = " --frame 30 --width 160 --height 90 -q ";
    const CliResult a =
        run_tumble(dir, "render default" + size + "--camera 1.5,-3,2:0.2,0,0.9:35 -o a.png");
    ASSERT_EQ(a.exit_code, 0) << a.err;
    // The same camera written into the scene, read by the scene loader.
    nlohmann::json scene = nlohmann::json::parse(source_file("assets/scenes/default.json"));
    scene["render"]["camera"] = {
        {"position", {1.5, -3, 2}}, {"target", {0.2, 0, 0.9}}, {"fov_deg", 35}};
    write_text(dir / "camera.json", scene.dump());
    const CliResult b = run_tumble(dir, "render camera.json" + size + "-o b.png");
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const render::Image ia = render::read_png(dir / "a.png"), ib = render::read_png(dir / "b.png");
    EXPECT_EQ(ia.rgb, ib.rgb);
    // Without the field of view, the scene's; a different camera draws a different picture.
    const CliResult c =
        run_tumble(dir, "render default" + size + "--camera 1.5,-3,2:0.2,0,0.9 -o c.png");
    ASSERT_EQ(c.exit_code, 0) << c.err;
    EXPECT_NE(render::read_png(dir / "c.png").rgb, ia.rgb);

    for (const char* bad : {"1,2:3,4,5", "1,2,3:4,5,6:7:8", "1,2,3", "a,b,c:0,0,0", "1,1,1:1,1,1",
                            "1,2,3:0,0,0:200", "sideways"}) {
        const CliResult r =
            run_tumble(dir, "render default" + size + "--camera " + bad + " -o x.png");
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_NE(r.err.find("--camera"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << bad;
    }
}

TEST(ScenesCli, ShowPrintsABuiltInSceneToStartFrom) {
    const auto dir = scratch_dir();
    for (const char* name :
         {"default", "lessons/intermediate_axis", "lessons/top_precession.json"}) {
        const CliResult r = run_tumble(dir, std::string("scenes --show ") + name);
        ASSERT_EQ(r.exit_code, 0) << name << r.err;
        std::string file = std::string("assets/scenes/") + name;
        if (!file.ends_with(".json")) file += ".json";
        EXPECT_EQ(r.out, source_file(file)) << name;
    }
    // Saved, it is a scene file that draws as the built-in one does (its mesh found built in).
    ASSERT_EQ(
        run_shell(dir, "\"$TUMBLE\" scenes --show lessons/top_precession > top.json").exit_code, 0);
    const std::string still = " --frame 10 --width 160 --height 90 -q -o ";
    ASSERT_EQ(run_tumble(dir, "render top.json" + still + "a.png").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, "render lessons/top_precession" + still + "b.png").exit_code, 0);
    EXPECT_EQ(render::read_png(dir / "a.png").rgb, render::read_png(dir / "b.png").rgb);
    // An unknown name is bad input naming the scenes there are.
    const CliResult bad = run_tumble(dir, "scenes --show nope");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("lessons/intermediate_axis"), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
}

} // namespace
} // namespace tumble::test
