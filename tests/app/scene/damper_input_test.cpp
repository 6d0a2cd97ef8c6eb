// A scene's "dampers" (docs/scene-format.md, physics/damper.h) read as written or refused with the
// file, the JSON path and what was expected, through `tumble render` and `tumble simulate` (exit 2,
// nothing written).
#include "support/bad_input_case.h"

namespace tumble::test {
namespace {

const std::string kGood = R"({
  "format_version": 1,
  "world": {"dt": 0.01, "duration": 0.1, "gravity": [0, 0, 0]},
  "render": {"width": 64, "height": 48, "fps": 10},
  "bodies": [
    {"name": "floor", "shape": {"type": "plane"}},
    {"name": "satellite", "shape": {"type": "box", "size": [0.2, 0.2, 1.0]}, "mass": 1.0,
     "position": [0, 0, 2], "angular_velocity": [0.1, 0, 5]},
    {"name": "rotor", "shape": {"type": "sphere", "radius": 0.1}, "mass": 1.0, "position": [1, 0, 2]}
  ],
  "dampers": [{"bodies": ["satellite", "rotor"], "coefficient": 0.01}]
})";

TEST(DamperInput, AGoodDamperRuns) {
    const auto dir = scratch_dir();
    write_text(dir / "good.json", kGood);
    const CliResult r = run_tumble(dir, "simulate good.json -q -o states.csv");
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(DamperInput, BadDampersAreRefusedWithTheirPlace) {
    const Case cases[] = {
        {"unknown_body",
         replace(kGood, "\"rotor\"]", "\"rotr\"]"),
         {"/dampers/0/bodies/1", "rotr", "rotor"}},
        {"same_body",
         replace(kGood, "[\"satellite\", \"rotor\"]", "[\"rotor\", \"rotor\"]"),
         {"/dampers/0/bodies", "two different bodies"}},
        {"both_static",
         replace(replace(kGood, "[\"satellite\", \"rotor\"]", "[\"floor\", \"floor2\"]"),
                 "\"bodies\": [\n",
                 "\"bodies\": [\n    {\"name\": \"floor2\", \"shape\": {\"type\": \"plane\"}, "
                 "\"position\": [0, 0, -1]},\n"),
         {"/dampers/0/bodies", "both are static"}},
        {"negative",
         replace(kGood, "\"coefficient\": 0.01", "\"coefficient\": -1"),
         {"/dampers/0/coefficient"}},
        {"three_bodies",
         replace(kGood, "[\"satellite\", \"rotor\"]", "[\"satellite\", \"rotor\", \"floor\"]"),
         {"/dampers/0/bodies"}},
        {"missing_coefficient",
         replace(kGood, ", \"coefficient\": 0.01", ""),
         {"/dampers/0", "coefficient"}},
    };
    for (const Case& c : cases) expect_refused(c);
}

} // namespace
} // namespace tumble::test
