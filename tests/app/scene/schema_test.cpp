// `tumble schema scene|suite`: the JSON Schemas an editor uses, generated from the loaders' own
// field tables. A real validator (Debian's python3-jsonschema, draft 2020-12) accepts every
// built-in scene and the example and project suites, and agrees with the loader on a set of bad
// scenes, each broken in one way a schema can state; docs/schemas/ holds the current output.
#include "support/bad_input_case.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace tumble::test {
namespace {

const std::filesystem::path kSource = TUMBLE_SOURCE_DIR;

// "valid" or "invalid ..." for each file, from tests/data/validate_json_schema.py.
std::map<std::string, std::string> validate(const std::filesystem::path& dir,
                                            const std::string& schema,
                                            const std::vector<std::string>& files) {
    std::string args;
    for (const std::string& f : files) args += " '" + f + "'";
    const CliResult r = run_shell(
        dir, "/usr/bin/python3 '" + (kSource / "tests/data/validate_json_schema.py").string() +
                 "' '" + schema + "'" + args);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err
                              << "\n(scripts/setup.sh installs python3-jsonschema)";
    std::map<std::string, std::string> out;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
        const bool valid = line.rfind("valid ", 0) == 0;
        const std::size_t start = valid ? 6 : 8;
        const std::size_t end = valid ? line.size() : line.find(": ", start);
        out[line.substr(start, end - start)] = line;
    }
    return out;
}

TEST(Schemas, TheCommittedSchemasAreTheGeneratedOnes) {
    const auto dir = scratch_dir();
    for (const char* kind : {"scene", "suite"}) {
        const CliResult r = run_tumble(dir, std::string("schema ") + kind);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(r.out, read_text(kSource / "docs/schemas" / (std::string(kind) + ".schema.json")))
            << "regenerate: tumble schema " << kind << " > docs/schemas/" << kind << ".schema.json";
    }
}

TEST(Schemas, EveryBuiltInSceneAndEveryCommittedSuiteIsValid) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_shell(dir, "\"$TUMBLE\" schema scene > scene.json && \"$TUMBLE\" schema suite "
                             "> suite.json")
                  .exit_code,
              0);
    // Every built-in scene, the lessons' (assets/scenes/lessons/) included: all that
    // app/CMakeLists.txt embeds.
    std::vector<std::string> scenes;
    for (const auto& e : std::filesystem::recursive_directory_iterator(kSource / "assets/scenes"))
        if (e.path().extension() == ".json") scenes.push_back(e.path().string());
    ASSERT_TRUE(std::any_of(scenes.begin(), scenes.end(), [](const std::string& s) {
        return s.find("/lessons/") != std::string::npos;
    })) << "the lesson scenes are built-in scenes too";
    for (const auto& [file, verdict] : validate(dir, "scene.json", scenes))
        EXPECT_EQ(verdict, "valid " + file);
    EXPECT_EQ(validate(dir, "scene.json", scenes).size(), scenes.size());
    const std::vector<std::string> suites = {(kSource / "tests/goldens/suite.json").string(),
                                             (kSource / "examples/regression/suite.json").string()};
    const auto verdicts = validate(dir, "suite.json", suites);
    ASSERT_EQ(verdicts.size(), suites.size());
    for (const auto& [file, verdict] : verdicts) EXPECT_EQ(verdict, "valid " + file);
    // The example's scenes, which are the user's own files.
    std::vector<std::string> examples;
    for (const auto& e :
         std::filesystem::directory_iterator(kSource / "examples/regression/scenes"))
        examples.push_back(e.path().string());
    for (const auto& [file, verdict] : validate(dir, "scene.json", examples))
        EXPECT_EQ(verdict, "valid " + file);
}

// A valid scene; each case breaks it in one way, or changes it in a way both must accept.
const char* kScene = R"({
  "$schema": "scene.schema.json",
  "format_version": 1,
  "world": {"dt": 0.01, "duration": 0.1, "integrator": "rk4", "substeps": 4},
  "render": {"width": 64, "height": 48, "fps": 10, "overlay": false,
             "camera": {"position": [3, -4, 2], "target": [0, 0, 0], "fov_deg": 40},
             "background": "#aabbcc"},
  "bodies": [
    {"name": "floor", "shape": {"type": "plane"}},
    {"shape": {"type": "box", "size": [0.2, 0.1, 0.3]}, "mass": 1.0, "position": [0, 0, 1],
     "angular_velocity": [0, 3, 0.1], "angular_velocity_frame": "body", "color": [0.2, 0.4, 0.6],
     "material": {"preset": "metal", "roughness": 0.3},
     "orientation": {"axis": [0, 0, 1], "angle_deg": 30}},
    {"shape": {"type": "capsule", "radius": 0.1, "length": 0.3}, "position": [1, 0, 1],
     "orientation": {"quaternion": [1, 0, 0, 0]}, "material": "rubber"}
  ]
})";

TEST(Schemas, TheSchemaAndTheLoaderAgreeOnBadScenes) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_shell(dir, "\"$TUMBLE\" schema scene > scene.schema.json").exit_code, 0);
    const std::vector<std::pair<const char*, std::string>> bad = {
        {"unknown_field", replace(kScene, "\"mass\"", "\"mas\"")},
        {"zero_mass", replace(kScene, "\"mass\": 1.0", "\"mass\": 0")},
        {"negative_dt", replace(kScene, "\"dt\": 0.01", "\"dt\": -0.01")},
        {"zero_fps", replace(kScene, "\"fps\": 10", "\"fps\": 0")},
        {"too_many_substeps", replace(kScene, "\"substeps\": 4", "\"substeps\": 65")},
        {"unknown_integrator", replace(kScene, "\"rk4\"", "\"verlet\"")},
        {"unknown_shape", replace(kScene, "\"box\"", "\"torus\"")},
        {"field_of_another_shape",
         replace(kScene, "\"radius\": 0.1, \"length\": 0.3", "\"radius\": 0.1, \"size\": 0.3")},
        {"capsule_without_length", replace(kScene, ", \"length\": 0.3", "")},
        {"bad_hex_colour", replace(kScene, "\"#aabbcc\"", "\"#aabbc\"")},
        {"colour_out_of_range", replace(kScene, "[0.2, 0.4, 0.6]", "[1.2, 0.4, 0.6]")},
        {"short_vector", replace(kScene, "\"position\": [0, 0, 1]", "\"position\": [0, 1]")},
        {"width_as_text", replace(kScene, "\"width\": 64", "\"width\": \"64\"")},
        {"overlay_as_text", replace(kScene, "\"overlay\": false", "\"overlay\": \"no\"")},
        {"unknown_preset", replace(kScene, "\"rubber\"", "\"wood\"")},
        {"roughness_out_of_range", replace(kScene, "\"roughness\": 0.3", "\"roughness\": 2")},
        {"wide_field_of_view", replace(kScene, "\"fov_deg\": 40", "\"fov_deg\": 200")},
        {"three_number_quaternion", replace(kScene, "[1, 0, 0, 0]", "[1, 0, 0]")},
        {"unknown_frame", replace(kScene, "\"body\",", "\"local\",")},
        {"angle_without_axis", replace(kScene, "\"axis\": [0, 0, 1], ", "")},
        {"missing_bodies", "{\"format_version\": 1}"},
        {"missing_version", replace(kScene, "\"format_version\": 1,", "")},
        {"unknown_world_field", replace(kScene, "\"substeps\"", "\"substep\"")},
        {"one_keyframe", replace(kScene, "\"fov_deg\": 40}",
                                 "\"fov_deg\": 40, \"path\": [{\"t\": 0, \"position\": [1, 1, 1], "
                                 "\"target\": [0, 0, 0]}]}")},
    };
    const std::vector<std::pair<const char*, std::string>> good = {
        {"as_given", kScene},
        {"auto_camera",
         replace(kScene, "\"position\": [3, -4, 2], \"target\": [0, 0, 0], ", "\"auto\": true, ")},
        {"radians", replace(kScene, "\"angle_deg\": 30", "\"angle_rad\": 0.5")},
        {"follow_by_index",
         replace(kScene, "\"fov_deg\": 40}", "\"fov_deg\": 40, \"follow\": {\"body\": 1}}")},
    };
    std::vector<std::string> files;
    for (const auto* set : {&bad, &good})
        for (const auto& [name, text] : *set) {
            write_text(dir / (std::string(name) + ".json"), text);
            files.push_back(std::string(name) + ".json");
        }
    const auto verdicts = validate(dir, "scene.schema.json", files);
    ASSERT_EQ(verdicts.size(), files.size());
    for (const auto* set : {&bad, &good})
        for (const auto& [name, text] : *set) {
            SCOPED_TRACE(name);
            const std::string file = std::string(name) + ".json";
            const bool refused = set == &bad;
            const CliResult loader = run_tumble(dir, "explain " + file);
            EXPECT_EQ(loader.exit_code, refused ? 2 : 0) << loader.err;
            EXPECT_EQ(verdicts.at(file).rfind("invalid", 0) == 0, refused) << verdicts.at(file);
        }
}

} // namespace
} // namespace tumble::test
