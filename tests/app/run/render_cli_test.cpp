// `tumble render` as a user runs it: the pipelined frames are the frames a still gives, they do
// not depend on llvmpipe's thread count, the picture switches and --stats work, and bad
// material or camera sections fail with their JSON path.
#include "render/png_io.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace tumble::test {
namespace {

// A small scene with a bit of everything: a checkered ground, a spinning box with axes, a ball
// in flight, materials, an orbiting camera and the overlay.
const char* kScene = R"({
  "format_version": 1,
  "world": {"duration": 0.5},
  "render": {"width": 160, "height": 96, "fps": 20, "overlay": true, "axes": true,
             "camera": {"position": [2, -3, 1.5], "target": [0, 0, 0.6], "orbit": {"period": 4}}},
  "bodies": [
    {"name": "ground", "shape": {"type": "plane"}, "normal": [0, 0, 1]},
    {"name": "box", "shape": {"type": "box", "size": [0.4, 0.2, 0.6]}, "position": [0, 0, 0.8],
     "gravity_scale": 0, "angular_velocity": [3, 0.1, 0.1], "material": "glossy"},
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.15}, "position": [-0.6, 0.3, 0.2],
     "velocity": [0.5, 0, 3], "material": {"preset": "metal", "roughness": 0.2},
     "color": "#d4a017"}
  ]
})";

render::Image image(const std::filesystem::path& p) {
    return render::read_png(p);
}

// run_tumble with environment variables set for the run, e.g. "LP_NUM_THREADS=1".
CliResult run_tumble_env(const std::filesystem::path& dir, const std::string& args,
                         const std::string& env) {
    const std::string cmd = "cd '" + dir.string() + "' && env " + env + " '" +
                            std::string(TUMBLE_EXE) + "' " + args + " > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = read_text(dir / "out.txt");
    r.err = read_text(dir / "err.txt");
    return r;
}

TEST(RenderCli, PipelinedFramesEqualStillsAndRepeatExactly) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene);
    CliResult r = run_tumble(dir, "render s.json -o seq/ -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run_tumble(dir, "render s.json -o seq2/%03d.png -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (int k : {0, 4, 9}) {
        char name[32];
        std::snprintf(name, sizeof name, "%06d.png", k);
        r = run_tumble(dir, "render s.json --frame " + std::to_string(k) + " -o still.png -q");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(image(dir / "still.png").rgb, image(dir / "seq" / name).rgb) << "frame " << k;
        std::snprintf(name, sizeof name, "%03d.png", k);
        EXPECT_EQ(image(dir / "seq" / (std::string("000") + name)).rgb,
                  image(dir / "seq2" / name).rgb)
            << "frame " << k;
    }
    // The orbit and the flight change the picture from frame to frame.
    EXPECT_NE(image(dir / "seq/000000.png").rgb, image(dir / "seq/000009.png").rgb);
}

TEST(RenderCli, FramesDoNotDependOnLlvmpipeThreadCount) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene);
    for (int threads : {1, 2, 4}) {
        const CliResult r =
            run_tumble_env(dir,
                           "render s.json --frame 6 --width 320 --height 192 -q -o t" +
                               std::to_string(threads) + ".png",
                           "LP_NUM_THREADS=" + std::to_string(threads));
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const render::Image one = image(dir / "t1.png");
    EXPECT_EQ(one.rgb, image(dir / "t2.png").rgb);
    EXPECT_EQ(one.rgb, image(dir / "t4.png").rgb);
}

TEST(RenderCli, SwitchesChangeThePictureAndStatsReportEveryStage) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene);
    auto still = [&](const std::string& flags, const std::string& name) {
        const CliResult r = run_tumble(dir, "render s.json --frame 5 -q -o " + name + " " + flags);
        EXPECT_EQ(r.exit_code, 0) << flags << r.err;
        return image(dir / name);
    };
    const render::Image all = still("", "all.png");
    for (const char* flag :
         {"--no-shadows", "--no-aa", "--no-overlay", "--no-axes", "--no-ao", "--reflections"})
        EXPECT_NE(still(flag, "x.png").rgb, all.rgb) << flag;
    const render::Image preview = still("--preview", "p.png");
    EXPECT_EQ(preview.width, 640);
    EXPECT_EQ(preview.height, 360);
    EXPECT_EQ(still("--preview --width 160 --height 96 --shadows --aa --ao", "pa.png").rgb,
              all.rgb);

    const CliResult r = run_tumble(dir, "render s.json -o null --stats -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* stage : {"physics", "render", "output", "end-to-end"})
        EXPECT_NE(r.err.find(stage), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("10 frames"), std::string::npos) << r.err;
}

std::vector<std::string> list_dir(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// One output rule (issue 14): a frame folder holding an earlier run's frames is refused (exit 2,
// the old frames kept) unless --overwrite, which leaves exactly this run's frames; missing parent
// folders are created (for study too: Study.QuickStudyWritesConsistentOutputs).
TEST(RenderCli, AStaleFrameFolderIsRefusedUnlessOverwriteAndParentsAreCreated) {
    const auto dir = scratch_dir();
    write_text(dir / "scene.json", kScene);
    const std::string run = "render scene.json --width 32 --height 20 -q -o deep/er/frames/";
    ASSERT_EQ(run_tumble(dir, run).exit_code, 0); // 0.5 s at 20 fps: 10 frames
    EXPECT_EQ(list_dir(dir / "deep/er/frames").size(), 10u);
    const CliResult again = run_tumble(dir, run + " --duration 0.1");
    EXPECT_EQ(again.exit_code, 2);
    EXPECT_NE(again.err.find("already holds 10 frames"), std::string::npos) << again.err;
    EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
    EXPECT_EQ(list_dir(dir / "deep/er/frames").size(), 10u);
    ASSERT_EQ(run_tumble(dir, run + " --duration 0.1 --overwrite").exit_code, 0);
    EXPECT_EQ(list_dir(dir / "deep/er/frames"),
              (std::vector<std::string>{"000000.png", "000001.png"}));
}

// --time SECONDS (issue 14): the still of the frame shown at that time, the same picture as
// --frame K for K = round(T fps); between frame times the nearest frame, with a note; outside the
// video refused with the range.
TEST(RenderCli, TimeGivesTheStillOfTheNearestFrame) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kScene); // 0.5 s at 20 fps: frames 0..9
    const std::string base = "render s.json --width 64 --height 40 ";
    ASSERT_EQ(run_tumble(dir, base + "--frame 5 -q -o frame.png").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, base + "--time 0.25 -q -o time.png").exit_code, 0);
    EXPECT_EQ(read_text(dir / "frame.png"), read_text(dir / "time.png"));
    const CliResult between = run_tumble(dir, base + "--time 0.26 -o between.png");
    EXPECT_EQ(between.exit_code, 0) << between.err;
    EXPECT_NE(between.err.find("between frames at 20 fps: frame 5, t = 0.25 s"), std::string::npos)
        << between.err;
    EXPECT_EQ(read_text(dir / "frame.png"), read_text(dir / "between.png"));
    const CliResult late = run_tumble(dir, base + "--time 0.6 -o late.png");
    EXPECT_EQ(late.exit_code, 2);
    EXPECT_NE(late.err.find("expected a time in [0, 0.45] s"), std::string::npos) << late.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "late.png"));
}

TEST(RenderCli, BadMaterialAndCameraAreNamedByPath) {
    const auto dir = scratch_dir();
    std::string scene = kScene;
    const auto at = scene.find("\"glossy\"");
    write_text(dir / "m.json", scene.replace(at, 8, "\"shiny\""));
    CliResult r = run_tumble(dir, "render m.json -o out.mp4");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("/bodies/1/material"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("plastic, glossy, matte, rubber, metal"), std::string::npos) << r.err;
    scene = kScene;
    const std::string orbit = "\"orbit\": {\"period\": 4}";
    write_text(dir / "c.json",
               scene.replace(scene.find(orbit), orbit.size(), "\"follow\": {\"body\": \"ghost\"}"));
    r = run_tumble(dir, "render c.json -o out.mp4");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("/render/camera/follow/body"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.mp4"));
}

} // namespace
} // namespace tumble::test
