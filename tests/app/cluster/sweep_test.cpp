// `tumble sweep`: one scene per combination, each as the scene reader reads it with the value
// set, and bad --set paths refused like bad scene fields, naming the file, the JSON path, what
// was expected and a suggestion.
#include "app/cluster/sweep.h"
#include "app/scene/scene.h"
#include "io/bad_input.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace tumble::app {
namespace {

namespace fs = std::filesystem;

TEST(Sweep, ValuesSplitAtTopLevelCommasAndWordsAreStrings) {
    const SweepSet s = parse_set("bodies.1.angular_velocity=[6,0.05,0.05],[6,0.5,0.5]");
    EXPECT_EQ(s.pointer(), "/bodies/1/angular_velocity");
    ASSERT_EQ(s.values.size(), 2u);
    EXPECT_EQ(s.values[1], nlohmann::json::parse("[6,0.5,0.5]"));
    const SweepSet w = parse_set("world.integrator=euler,rk4,\"a,b\"");
    ASSERT_EQ(w.values.size(), 3u);
    EXPECT_EQ(w.values[0], "euler");
    EXPECT_EQ(w.values[2], "a,b");
    EXPECT_EQ(parse_set("/world/dt=0.001").values[0], 0.001);
    EXPECT_THROW(parse_set("world.dt"), io::BadInput);
    EXPECT_THROW(parse_set("world.dt=1,,2"), io::BadInput);
    EXPECT_THROW(parse_set("world..dt=1"), io::BadInput);
}

TEST(Sweep, OneSceneForEachCombinationLastSetFastest) {
    const Sweep s = make_sweep("default", {"world.integrator=euler,rk4,splitting",
                                           "bodies.1.angular_velocity=[6,0.05,0.05],[6,0.5,0.5]"});
    ASSERT_EQ(s.scenes.size(), 6u);
    const char* integrators[] = {"euler", "euler", "rk4", "rk4", "splitting", "splitting"};
    for (std::size_t i = 0; i < 6; ++i) {
        const SweepScene& c = s.scenes[i];
        EXPECT_EQ(c.file, "scene_00" + std::to_string(i) + ".json");
        // Read back by the scene reader, the fields hold the values of this combination.
        const Scene read = load_scene(c.scene.dump(), c.file);
        EXPECT_EQ(physics::integrator_info(read.world.integrator).name, integrators[i]);
        EXPECT_EQ(c.scene["bodies"][1]["angular_velocity"][1], i % 2 ? 0.5 : 0.05);
        EXPECT_EQ(c.scene["bodies"][1]["angular_velocity_frame"], "body"); // the rest kept
    }
    const nlohmann::json m = sweep_manifest(s);
    EXPECT_EQ(m["scenes"][3]["set"]["world.integrator"], "rk4");
    EXPECT_EQ(m["source"], "builtin:default.json");
}

std::string refusal(const std::vector<std::string>& sets) {
    try {
        make_sweep("default", sets);
    } catch (const io::BadInput& e) {
        return e.what();
    }
    return "accepted";
}

TEST(Sweep, BadSetsAreRefusedLikeBadSceneFields) {
    const std::string typo = refusal({"world.integrater=euler"});
    for (const char* part : {"--set world.integrater", "builtin:default.json", "/world/integrater",
                             "did you mean \"integrator\""})
        EXPECT_NE(typo.find(part), std::string::npos) << typo;
    EXPECT_NE(refusal({"wrld.dt=0.01"}).find("did you mean \"world\""), std::string::npos);
    EXPECT_NE(refusal({"bodies.9.mass=1"}).find("/bodies: expected an index into this array of 5"),
              std::string::npos);
    EXPECT_NE(refusal({"world.dt=0.01,-1"}).find("/world/dt: expected a positive time step"),
              std::string::npos);
    EXPECT_NE(refusal({"world.integrator=rk4,eulr"}).find("unknown integrator \"eulr\""),
              std::string::npos);
    EXPECT_NE(refusal({"world.dt.x=1"}).find("/world/dt: is 0.004"), std::string::npos);
}

TEST(Sweep, TheFolderIsWrittenWholeOrNotAtAll) {
    const fs::path root = fs::path(TUMBLE_TEST_ARTIFACTS) / "sweep";
    fs::remove_all(root);
    const Sweep s = make_sweep("default", {"world.integrator=euler,rk4"});
    write_sweep(s, root / "a/");
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(root / "a")) files.push_back(e.path().filename());
    std::sort(files.begin(), files.end());
    EXPECT_EQ(files,
              (std::vector<std::string>{"manifest.json", "scene_000.json", "scene_001.json"}));
    std::ifstream in(root / "a/scene_001.json");
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(load_scene(text.str(), "scene_001.json").world.integrator, physics::Integrator::Rk4);
    EXPECT_THROW(write_sweep(s, root / "a"), io::BadInput); // not empty: refused
    for (const auto& e : fs::directory_iterator(root))
        EXPECT_EQ(e.path().filename(), "a") << "a temporary folder was left behind";
}

} // namespace
} // namespace tumble::app
