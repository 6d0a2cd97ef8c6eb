// State checks: a golden trajectory perturbed by known amounts at known times fails naming each
// body, quantity, first time and amount; the deviations are the distances they claim to be; and
// bad suites name the file and the JSON path.
#include "app/regression/state_compare.h"
#include "app/regression/suite_support.h"

#include <cmath>

namespace tumble::test {
namespace {

// default_states samples every 30th frame (0.5 s at 60 fps) of the default scene.
TEST(StateChecks, APerturbedGoldenNamesBodyQuantityFirstTimeAndAmount) {
    const auto dir = scratch_dir();
    const auto goldens = copy_goldens(dir);
    // From t = 3 s on, "ball e=0.7" stood 2.5 mm higher in the golden (column z).
    edit_csv(goldens / "default_states.csv", [](std::vector<std::string>& f) {
        if (f[3] == "\"ball e=0.7\"" && std::stod(f[1]) >= 3.0) f[6] = shifted(f[6], 2.5e-3);
    });
    // At t = 4.5 s only, the scene's energy was 0.01 J more.
    edit_csv(goldens / "default_states.diagnostics.csv", [](std::vector<std::string>& f) {
        if (std::stod(f[1]) == 4.5) f[4] = shifted(f[4], 0.01);
    });
    const CliResult r = run_tumble(dir, "test goldens/suite.json --filter default_states "
                                        "--junit j.xml");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    const std::string position = "body \"ball e=0.7\" position: out of tolerance from t = 3 s "
                                 "(frame 180) by 0.0025 m (tolerance 1e-06 m)";
    const std::string energy = "energy: out of tolerance from t = 4.5 s (frame 270) by 0.01 J "
                               "(tolerance 1e-06 J); largest 0.01 J at t = 4.5 s (frame 270)";
    // The summary names the first to leave its tolerance; the details list every one.
    EXPECT_TRUE(contains(r.out, "FAIL   default_states: " + position)) << r.out;
    EXPECT_TRUE(contains(r.out, "; 1 more out of tolerance")) << r.out;
    EXPECT_TRUE(contains(r.out, "         " + energy)) << r.out;
    EXPECT_FALSE(contains(r.out, "body \"book\" position: out")) << r.out;
    const std::string junit = read_text(dir / "j.xml");
    EXPECT_TRUE(contains(junit, "out of tolerance from t = 3 s (frame 180) by 0.0025 m")) << junit;
}

TEST(StateChecks, DeviationsAreDistancesAnglesAndDifferences) {
    using app::StateQuantity;
    app::StateRow a, g;
    g.x = {1, 2, 3}, a.x = {1, 2 + 0.3, 3 + 0.4}; // a 3-4-5 triangle
    EXPECT_DOUBLE_EQ(app::deviation(StateQuantity::kPosition, a, g), 0.5);
    g.q = physics::Quat(Eigen::AngleAxisd(0.2, physics::Vec3(1, 2, 3).normalized()));
    a.q = g.q * physics::Quat(Eigen::AngleAxisd(0.7, physics::Vec3::UnitY()));
    EXPECT_NEAR(app::deviation(StateQuantity::kOrientation, a, g), 0.7, 1e-12);
    a.q.coeffs() *= -1.0; // the same rotation
    EXPECT_NEAR(app::deviation(StateQuantity::kOrientation, a, g), 0.7, 1e-12);
    g.w = {0, 0, 5}, a.w = {0, 0, -5};
    EXPECT_DOUBLE_EQ(app::deviation(StateQuantity::kAngularVelocity, a, g), 10.0);
    app::DiagnosticsRow da, dg;
    da.energy = 3.25, dg.energy = 3.0;
    EXPECT_DOUBLE_EQ(app::deviation(StateQuantity::kEnergy, da, dg), 0.25);
    da.p = {0, 1, 0};
    EXPECT_DOUBLE_EQ(app::deviation(StateQuantity::kMomentum, da, dg), 1.0);
}

struct BadSuite {
    const char* name;
    std::string text;
    std::string message; // after "suite.json: "
};

// A scene whose two bodies share a name: a state check could not tell their rows apart.
const char* kTwins = R"({"format_version": 1, "bodies": [
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.1}},
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "position": [1, 0, 0]}]})";

std::string scene_with(const std::string& checks) {
    return R"({"format_version": 1, "scenes": [{"scene": "tossed_book", )" + checks + "}]}";
}

TEST(StateChecks, BadSuitesNameTheFileAndTheJsonPath) {
    const std::vector<BadSuite> cases = {
        {"negative_tolerance", scene_with(R"("states": [{"every": 10, "bodies": ["book"],
                        "quantities": {"velocity": 1e-9, "position": -1}}])"),
         "/scenes/0/states/0/quantities/position: expected a tolerance >= 0 in metres"},
        {"unknown_quantity",
         scene_with(
             R"("states": [{"every": 10, "bodies": ["book"], "quantities": {"postion": 1}}])"),
         "/scenes/0/states/0/quantities/postion: unknown field \"postion\" (did you mean "
         "\"position\"?)"},
        {"unknown_body",
         scene_with(
             R"("states": [{"every": 10, "bodies": ["boook"], "quantities": {"position": 1}}])"),
         "/scenes/0/states/0/bodies/0: no body named \"boook\" in builtin:tossed_book.json "
         "(bodies: ground, book)"},
        {"body_quantity_without_bodies",
         scene_with(R"("states": [{"every": 10, "quantities": {"orientation": 1}}])"),
         "/scenes/0/states/0: position, orientation, velocity and angular_velocity are per body"},
        {"frame_out_of_range", scene_with(R"("images": [{"frames": [0, 180]}])"),
         "/scenes/0/images/0/frames/1: expected a frame index in [0, 179] (the scene has 180 "
         "frames: 3 s at 60 fps)"},
        {"time_out_of_range", scene_with(R"("images": [{"times": [3.5]}])"),
         "/scenes/0/images/0/times/0: expected a time at most 2.98"},
        {"two_samplings", scene_with(R"("images": [{"frames": [0], "every": 5}])"),
         "/scenes/0/images/0: give exactly one of \"frames\", \"every\" and \"times\""},
        {"mask_outside", scene_with(R"("images": [{"frames": [0],
                          "masks": [{"x": 300, "y": 0, "width": 21, "height": 5}]}])"),
         "/scenes/0/images/0/masks/0: expected a rectangle inside the 320x180 image"},
        {"same_name_twice", scene_with(R"("images": [{"frames": [0]}, {"every": 90}])"),
         "/scenes/0/images/1: two checks are named tossed_book_0000 (the other is at "
         "/scenes/0/images/0); give one of them a \"name\""},
        // A check's name becomes a golden's file name: a '/' would put it in another folder.
        {"image_name_leaving_the_folder",
         scene_with(R"("images": [{"frames": [0], "name": "../x"}])"),
         "/scenes/0/images/0/name: expected a name of letters, digits, '_', '.' and '-' (starting "
         "with a letter or digit), got \"../x\""},
        {"state_name_with_a_space",
         scene_with(R"("states": [{"every": 10, "quantities": {"energy": 1}, "name": "a b"}])"),
         "/scenes/0/states/0/name: expected a name of letters, digits, '_', '.' and '-'"},
        {"scene_name_starting_with_a_dot",
         scene_with(R"("name": ".hidden", "images": [{"frames": [0]}])"),
         "/scenes/0/name: expected a name of letters, digits, '_', '.' and '-'"},
        {"no_checks", scene_with(R"("images": [])"),
         "/scenes/0: expected \"images\" or \"states\" checks"},
        {"bad_compare", scene_with(R"("images": [{"frames": [0], "compare": {"tolerance": 300}}])"),
         "/scenes/0/images/0/compare/tolerance: expected a per-channel tolerance, 0..255 in [0, "
         "255], got 300"},
        {"missing_scene", R"({"format_version": 1, "scenes": [{"scene": "nowhere.json",
                             "images": [{"frames": [0]}]}]})",
         "/scenes/0/scene: no scene file nowhere.json and no built-in scene \"nowhere.json\""},
        {"version", R"({"format_version": 2, "scenes": []})",
         "/format_version: this tumble reads suite format_version 1, got 2"},
        {"no_scenes", R"({"format_version": 1, "scenes": []})",
         "/scenes: expected scenes and their checks (at least 1), got []"},
    };
    for (const BadSuite& c : cases) {
        SCOPED_TRACE(c.name);
        const auto dir = scratch_dir() / c.name;
        std::filesystem::create_directories(dir);
        write_text(dir / "suite.json", c.text);
        const CliResult r = run_tumble(dir, "test suite.json --junit j.xml --report rep");
        EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
        EXPECT_TRUE(contains(r.err, "tumble: error: suite.json: " + c.message)) << r.err;
        EXPECT_EQ(files_in(dir), std::vector<std::string>{"suite.json"}); // nothing written
    }
}

TEST(StateChecks, ABodyNameThatTwoBodiesShareIsRefused) {
    const auto dir = scratch_dir();
    write_text(dir / "twins.json", kTwins);
    write_text(dir / "suite.json", R"({"format_version": 1, "scenes": [{"scene": "twins.json",
        "states": [{"frames": [0], "bodies": ["ball"], "quantities": {"position": 0}}]}]})");
    const CliResult r = run_tumble(dir, "test suite.json");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "suite.json: /scenes/0/states/0/bodies/0: bodies 0 and 1 of "
                                "twins.json are both named \"ball\""))
        << r.err;
}

} // namespace
} // namespace tumble::test
