// One scene, one trajectory, whichever command runs it (issue 27, app/run/prepare_run.h). A scene
// with world.integrator "auto" is resolved by pilot runs to an integrator and a step; every
// command must run that same plan: `tumble simulate` (the CSV), `tumble test` (the goldens it
// writes: they record what users get), `tumble render` (its frames, compared pixel for pixel with
// the suite's images of the same frames), checkpoints (their states against the CSV, and a render
// continued from one) and shards (the joined video against a single render).
#include "app/cluster/checkpoint.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace tumble::test {
namespace {

namespace fs = std::filesystem;

// A book flipping about its middle axis, torque-free: "auto" at 1e-6 picks an integrator and a
// step other than the scene's dt (1/30 s here: the pilots take several steps per frame).
const std::string kScene = R"({
  "format_version": 1,
  "world": {"gravity": [0, 0, 0], "dt": 0.03333333333333333, "integrator": "auto",
            "tolerance": 1e-6, "duration": 2},
  "render": {"width": 160, "height": 90, "fps": 30,
             "camera": {"position": [0.95, -1.9, 1.45], "target": [0, 0, 0.95], "fov_deg": 40}},
  "bodies": [
    {"name": "ground", "shape": {"type": "plane", "extent": 20}},
    {"name": "book", "shape": {"type": "box", "size": [0.22, 0.05, 0.30]}, "mass": 0.8,
     "position": [0, 0, 1.0], "angular_velocity": [6.0, 0.05, 0.05],
     "angular_velocity_frame": "body"}
  ]
})";

const std::string kSuite = R"({
  "format_version": 1,
  "title": "auto everywhere",
  "goldens": "goldens",
  "image_defaults": {"width": 160, "height": 90},
  "scenes": [{"scene": "flip.json", "images": [{"frames": [0, 37, 59]}],
              "states": [{"bodies": ["book"], "every": 1,
                          "quantities": {"orientation": 1e-12}}]}]
})";

// The CSV's rows by step: step -> the row (the header and a '#' scene record, which `tumble
// simulate` writes first, kept out).
std::map<long, std::string> rows_by_step(const std::string& csv) {
    std::map<long, std::string> rows;
    std::istringstream lines(csv);
    for (std::string line; std::getline(lines, line);)
        if (!line.empty() && line[0] != '#' && line.rfind("step,", 0) != 0)
            rows[std::stol(line.substr(0, line.find(',')))] = line;
    return rows;
}

// A PNG's pixels as raw RGB bytes, decoded by ffmpeg (two encoders may compress alike pixels
// differently).
std::string pixels(const fs::path& dir, const std::string& png) {
    const CliResult r =
        run_shell(dir, "ffmpeg -v error -i '" + png + "' -f rawvideo -pix_fmt rgb24 -");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(r.out.empty()) << png;
    return r.out;
}

class PrepareRun : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = scratch_dir();
        write_text(dir / "flip.json", kScene);
        write_text(dir / "suite.json", kSuite);
    }
    fs::path dir;
};

// simulate and `tumble test`: the goldens written by --update are the simulate CSV's rows, to
// every digit (%.17g: the same doubles), and the plan's integrator is what simulate reports.
TEST_F(PrepareRun, TheSuiteRecordsTheTrajectorySimulateWrites) {
    const CliResult sim = run_tumble(dir, "simulate flip.json -o flip.csv");
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    ASSERT_NE(sim.err.find("auto: "), std::string::npos) << sim.err;
    const CliResult update = run_tumble(dir, "test suite.json --update");
    ASSERT_EQ(update.exit_code, 0) << update.err << update.out;
    const std::map<long, std::string> simulated = rows_by_step(read_text(dir / "flip.csv"));
    std::map<long, std::string> golden;
    for (const auto& e : fs::directory_iterator(dir / "goldens"))
        if (e.path().filename().string().ends_with("_states.csv"))
            golden = rows_by_step(read_text(e.path()));
    ASSERT_GE(golden.size(), 60u) << "a row per frame";
    // steps_per_frame > 1: the frames' steps are multiples of it, and not every step
    ASSERT_GT(simulated.size(), golden.size());
    for (const auto& [step, row] : golden) {
        ASSERT_TRUE(simulated.count(step)) << "no simulate row at step " << step;
        EXPECT_EQ(row, simulated.at(step)) << "step " << step;
    }
    // And the suite passes against them (a run of its own, planned again).
    const CliResult check = run_tumble(dir, "test suite.json");
    EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

// render: each still is the suite's image of the same frame, pixel for pixel.
TEST_F(PrepareRun, RenderedFramesAreTheSuitesFrames) {
    ASSERT_EQ(run_tumble(dir, "test suite.json --update").exit_code, 0);
    int compared = 0;
    for (const int k : {37, 59}) {
        char still[16], args[96];
        std::snprintf(still, sizeof still, "r%d.png", k);
        std::snprintf(args, sizeof args, "render flip.json --no-overlay --frame %d -o %s", k,
                      still);
        const CliResult r = run_tumble(dir, args);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        for (const auto& e : fs::directory_iterator(dir / "goldens")) {
            const std::string name = e.path().filename().string();
            char suffix[16];
            std::snprintf(suffix, sizeof suffix, "_%04d.png", k);
            if (!name.ends_with(suffix)) continue;
            EXPECT_EQ(pixels(dir, still), pixels(dir, "goldens/" + name)) << "frame " << k;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 2);
}

// checkpoints: each checkpoint's state is the simulate CSV's row of that frame, and a render
// continued from one draws what a render from t = 0 draws.
TEST_F(PrepareRun, CheckpointsHoldTheSimulatedStates) {
    ASSERT_EQ(run_tumble(dir, "simulate flip.json -o flip.csv").exit_code, 0);
    const CliResult ck =
        run_tumble(dir, "simulate flip.json --checkpoint-every 20 --checkpoints ck -q");
    ASSERT_EQ(ck.exit_code, 0) << ck.err;
    const std::map<long, std::string> simulated = rows_by_step(read_text(dir / "flip.csv"));
    int checked = 0;
    for (const auto& e : fs::directory_iterator(dir / "ck")) {
        const app::Checkpoint c = app::read_checkpoint(e.path());
        const long step = static_cast<long>(c.state.step);
        ASSERT_TRUE(simulated.count(step)) << e.path();
        const std::string& row = simulated.at(step);
        char x[128];
        std::snprintf(x, sizeof x, ",%.17g,%.17g,%.17g,", c.state.q[1].w(), c.state.q[1].x(),
                      c.state.q[1].y());
        EXPECT_NE(row.find(x), std::string::npos) << "checkpoint " << e.path() << " vs " << row;
        ++checked;
    }
    EXPECT_EQ(checked, 2);
    const CliResult cont = run_tumble(dir, "render flip.json --frames 40:60 --from-checkpoints ck "
                                           "-o cont/ -q");
    ASSERT_EQ(cont.exit_code, 0) << cont.err;
    ASSERT_EQ(run_tumble(dir, "render flip.json --frame 59 -o whole.png -q").exit_code, 0);
    EXPECT_EQ(read_text(dir / "cont/000059.png"), read_text(dir / "whole.png"));
}

// shards: `tumble shards` plans each shard's render the same way; the joined video decodes to
// the frames of one render (4 s: two key-frame segments of 2 s, one per shard).
TEST_F(PrepareRun, ShardsJoinToTheSingleRender) {
    ASSERT_EQ(run_tumble(dir, "render flip.json --duration 4 -q -o single.mp4").exit_code, 0);
    const CliResult plan = run_tumble(dir, "shards flip.json --duration 4 --count 2 -o out/j.mp4 "
                                           "--tumble \"$TUMBLE\" -q > plan.sh && sh plan.sh && "
                                           "\"$TUMBLE\" join out/j.part000.mp4 out/j.part001.mp4 "
                                           "-o out/j.mp4");
    ASSERT_EQ(plan.exit_code, 0) << plan.err;
    const CliResult a =
        run_shell(dir, "ffmpeg -v error -i single.mp4 -f framemd5 - | grep -v '^#'");
    const CliResult b = run_shell(dir, "ffmpeg -v error -i out/j.mp4 -f framemd5 - | grep -v '^#'");
    ASSERT_EQ(a.exit_code, 0);
    EXPECT_EQ(std::count(a.out.begin(), a.out.end(), '\n'), 120);
    EXPECT_EQ(a.out, b.out);
}

} // namespace
} // namespace tumble::test
