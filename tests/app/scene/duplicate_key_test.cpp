// A key given twice in one object of a scene is refused (exit 2) naming the file, the JSON path
// of the second one and both places as line:column; the parser alone would keep the last one
// silently. The same key in two different objects is fine.
#include "support/bad_input_case.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

namespace tumble::test {
namespace {

// Line 5 is the body; its "mass" starts at column 88.
const char* kGood = R"({
  "format_version": 1,
  "world": {"dt": 0.01, "duration": 0.1, "integrator": "rk4"},
  "bodies": [
    {"shape": {"type": "box", "size": [0.2, 0.1, 0.3]}, "material": {"friction": 0.5}, "mass": 1.0}
  ]
})";

std::vector<Case> cases() {
    return {
        {"top_level",
         replace(kGood, "\"format_version\": 1,", "\"format_version\": 1, \"format_version\": 1,"),
         {"bad.json: /format_version: duplicate key \"format_version\"",
          "first at 2:3, again at 2:24"}},
        {"world",
         replace(kGood, "\"dt\": 0.01,", "\"dt\": 0.01, \"dt\": 0.02,"),
         {"/world/dt", "first at 3:13, again at 3:25"}},
        {"body",
         replace(kGood, "\"mass\": 1.0", "\"mass\": -5, \"mass\": 1.0"),
         {"/bodies/0/mass", "duplicate key \"mass\"", "first at 5:88, again at 5:100"}},
        {"nested_material",
         replace(kGood, "{\"friction\": 0.5}", "{\"friction\": 0.5, \"friction\": 0.6}"),
         {"/bodies/0/material/friction", "first at 5:70, again at 5:87"}},
        {"escaped_spelling",
         replace(kGood, "\"mass\": 1.0", "\"mass\": 1.0, \"m\\u0061ss\": 2"),
         {"/bodies/0/mass", "first at 5:88, again at 5:101"}},
        {"second_body",
         replace(kGood, "\"mass\": 1.0}",
                 "\"mass\": 1.0},\n    {\"shape\": {\"type\": "
                 "\"sphere\", \"radius\": 1, \"radius\": 2}}"),
         {"/bodies/1/shape/radius", "first at 6:34, again at 6:47"}},
    };
}

TEST(DuplicateKeys, AKeyTwiceInOneObjectIsRefusedNamingPathAndBothPlaces) {
    for (const Case& c : cases()) expect_refused(c);
}

TEST(DuplicateKeys, TheSameKeyInDifferentObjectsAndInStringsIsFine) {
    const auto dir = scratch_dir();
    // "type" and "name" in two bodies, "size" as a key and inside a name that also holds an
    // escaped quote and braces: no duplicates.
    std::string scene = replace(kGood, "\"mass\": 1.0}", R"("mass": 1.0, "name": "size \" }{ x"},
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "position": [0, 0, 2]})");
    write_text(dir / "ok.json", scene);
    const CliResult r = run_tumble(dir, "simulate ok.json -o states.csv -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

} // namespace
} // namespace tumble::test
