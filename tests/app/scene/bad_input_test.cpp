// Bad input gets one clear message naming the file, the place and what was expected, a non-zero
// exit, and leaves no output file behind.
#include "support/bad_input_case.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

namespace tumble::test {
namespace {

// A valid minimal scene; each case below breaks one thing in it.
const char* kGood = R"({
  "format_version": 1,
  "world": {"dt": 0.01, "duration": 0.1, "integrator": "rk4"},
  "render": {"width": 64, "height": 48, "fps": 10},
  "bodies": [
    {"shape": {"type": "box", "size": [0.2, 0.1, 0.3]}, "mass": 1.0, "angular_velocity": [0, 3, 0.1]}
  ]
})";

std::vector<Case> cases() {
    return {
        {"syntax",
         replace(kGood, "\"mass\": 1.0,", "\"mass\": 1.0,,"),
         {"bad.json:6:", "invalid JSON"}},
        {"unknown_field",
         replace(kGood, "\"mass\"", "\"mas\""),
         {"/bodies/0/mas", "unknown field", "did you mean \"mass\""}},
        {"unknown_shape",
         replace(kGood, "\"box\"", "\"torus\""),
         {"/bodies/0/shape/type", "unknown shape \"torus\"", "sphere, box, plane"}},
        {"zero_mass",
         replace(kGood, "\"mass\": 1.0", "\"mass\": 0"),
         {"/bodies/0/mass", "positive mass"}},
        {"negative_mass", replace(kGood, "\"mass\": 1.0", "\"mass\": -2"), {"/bodies/0/mass"}},
        {"zero_inertia",
         replace(kGood, "\"mass\": 1.0", "\"mass\": 1.0, \"inertia\": [1, 0, 1]"),
         {"/bodies/0/inertia", "positive"}},
        {"triangle_inertia",
         replace(kGood, "\"mass\": 1.0", "\"mass\": 1.0, \"inertia\": [1, 1, 3]"),
         {"/bodies/0/inertia", "triangle inequality"}},
        {"non_finite",
         replace(kGood, "\"mass\": 1.0", "\"mass\": 1e999"),
         {"bad.json:6:", "non-finite"}},
        {"zero_dt",
         replace(kGood, "\"dt\": 0.01", "\"dt\": 0"),
         {"/world/dt", "positive time step"}},
        {"negative_dt", replace(kGood, "\"dt\": 0.01", "\"dt\": -0.01"), {"/world/dt"}},
        {"zero_fps",
         replace(kGood, "\"fps\": 10", "\"fps\": 0"),
         {"/render/fps", "frames per second"}},
        {"zero_width", replace(kGood, "\"width\": 64", "\"width\": 0"), {"/render/width"}},
        {"unknown_integrator",
         replace(kGood, "\"rk4\"", "\"verlet\""),
         {"/world/integrator", "unknown integrator \"verlet\"", "rk4"}},
        {"version",
         replace(kGood, "\"format_version\": 1", "\"format_version\": 7"),
         {"/format_version", "reads format_version 1"}},
        {"missing_bodies", "{\"format_version\": 1}", {"missing required field \"bodies\""}},
    };
}

TEST(BadInput, EveryKindOfBadSceneExitsNonZeroWithItsMessageAndNoOutput) {
    for (const Case& c : cases()) expect_refused(c);
}

TEST(BadInput, UnknownIntegratorOnTheCommandLineListsTheValidOnes) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "render --integrator nope -o out.mp4");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("valid integrators: euler, euler_momentum, symplectic_euler, "
                         "implicit_gyro, rk4, splitting, midpoint, splitting4"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(files_in(dir).empty());
}

TEST(BadInput, OddVideoDimensionsAreRefusedAndNothingIsWritten) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "render --width 65 --height 48 --duration 0.1 -o out.mp4");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("even"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
}

TEST(BadInput, MissingSceneFileNamesItAndListsBuiltins) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "render nowhere.json -o out.mp4");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("nowhere.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("default"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
}

TEST(BadInput, ExistingOutputSurvivesAFailedRun) {
    const auto dir = scratch_dir();
    write_text(dir / "out.mp4", "precious");
    write_text(dir / "bad.json", replace(kGood, "\"mass\": 1.0", "\"mass\": -1"));
    EXPECT_EQ(run_tumble(dir, "render bad.json -o out.mp4").exit_code, 2);
    EXPECT_EQ(read_text(dir / "out.mp4"), "precious");
}

} // namespace
} // namespace tumble::test
