// `tumble test` as users run it, on copies of the project's own suite (tests/goldens/suite.json;
// CTest also runs the suite itself: Goldens.ProjectSuiteThroughTumbleTest) and on small suites
// written here: every built-in scene is guarded by images and states, a broken golden fails
// that check alone, a missing golden is one failing check that says how to create it, updates
// refuse another renderer's goldens, and bad suites and empty selections are bad input.
#include "app/regression/suite_support.h"
#include "support/interrupt_runner.h"

#include <nlohmann/json.hpp>

#include <set>

namespace tumble::test {
namespace {

// A scene added to assets/scenes without checks fails here, saying how to add them.
TEST(RegressionSuite, EveryBuiltInSceneHasAnImageAndAStateCheck) {
    const auto dir = scratch_dir();
    const CliResult scenes = run_tumble(dir, "scenes");
    ASSERT_EQ(scenes.exit_code, 0);
    const nlohmann::json suite = nlohmann::json::parse(read_text(kProjectGoldens / "suite.json"));
    std::set<std::string> imaged, stated;
    for (const auto& s : suite["scenes"]) {
        if (s.contains("images") && !s["images"].empty()) imaged.insert(s["scene"]);
        if (s.contains("states") && !s["states"].empty()) stated.insert(s["scene"]);
    }
    int listed = 0;
    for (const auto& e : std::filesystem::directory_iterator(
             std::filesystem::path(TUMBLE_SOURCE_DIR) / "assets/scenes")) {
        if (e.path().extension() != ".json") continue;
        const std::string name = e.path().stem().string();
        ++listed;
        EXPECT_TRUE(contains(scenes.out, name)) << name << " is not listed by `tumble scenes`";
        EXPECT_TRUE(imaged.count(name) && stated.count(name))
            << "scene " << name << " needs image and state checks in tests/goldens/suite.json; "
            << "add its entry, then scripts/update-goldens.sh --filter " << name;
    }
    EXPECT_GE(listed, 9);
}

TEST(RegressionSuite, ACorruptedGoldenFailsThatCheckAloneWithItsNumbers) {
    const auto dir = scratch_dir();
    paint_square(copy_goldens(dir) / "default_0150.png", 10, 10, 20); // 400 px; 40 allowed
    const CliResult r = run_tumble(dir, "test goldens/suite.json --filter 'default*'");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "FAIL   default_0150: ")) << r.out;
    EXPECT_TRUE(contains(r.out, " pixels differ (allowed 40)")) << r.out;
    EXPECT_TRUE(contains(r.out, "update: tumble test goldens/suite.json --update --filter "
                                "default_0150"))
        << r.out;
    for (const char* ok :
         {"ok     default_0000: ", "ok     default_0000_overlay: ", "ok     default_states: "})
        EXPECT_TRUE(contains(r.out, ok)) << ok << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "4 checks: 3 passed, 1 failed")) << r.out;
}

TEST(RegressionSuite, AMissingGoldenIsOneFailingCheckThatSaysHowToCreateIt) {
    const auto dir = scratch_dir();
    const auto goldens = copy_goldens(dir);
    const render::Image committed = render::read_png(goldens / "default_0150.png");
    const std::string states = read_text(goldens / "default_states.csv");
    std::filesystem::remove(goldens / "default_0150.png");
    std::filesystem::remove(goldens / "default_states.csv");
    CliResult r = run_tumble(dir, "test goldens/suite.json --filter default");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    const std::string create = "tumble test goldens/suite.json --update --filter default_0150";
    EXPECT_TRUE(contains(r.out, "FAIL   default_0150: no golden image goldens/default_0150.png; "
                                "create it with: " +
                                    create))
        << r.out;
    EXPECT_TRUE(contains(r.out, "FAIL   default_states: no golden trajectory")) << r.out;
    EXPECT_TRUE(contains(r.out, "4 checks: 2 passed, 2 failed")) << r.out;
    // The command it gives, as given: writes that golden only.
    r = run_shell(dir, "\"$TUMBLE\"" + create.substr(6));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "added   goldens/default_0150.png")) << r.out;
    EXPECT_FALSE(std::filesystem::exists(goldens / "default_states.csv"));
    // This build draws the frame the committed golden holds.
    EXPECT_EQ(render::read_png(goldens / "default_0150.png").rgb, committed.rgb);
    r = run_tumble(dir, "test goldens/suite.json --update --filter default");
    EXPECT_TRUE(contains(r.out, "added   goldens/default_states.csv")) << r.out;
    EXPECT_TRUE(contains(r.out, "1 golden(s) written, 3 unchanged")) << r.out;
    // Bit for bit, below the line that records the scene it was made from (a committed golden
    // older than that record has none).
    const std::string made = read_text(goldens / "default_states.csv");
    EXPECT_TRUE(made.starts_with("# tumble scene {")) << made.substr(0, 80);
    const auto below_record = [](const std::string& csv) {
        return csv.starts_with("# tumble scene {") ? csv.substr(csv.find('\n') + 1) : csv;
    };
    EXPECT_EQ(below_record(made), below_record(states));
    EXPECT_EQ(run_tumble(dir, "test goldens/suite.json --filter default").exit_code, 0);
}

TEST(RegressionSuite, UpdateRefusesGoldensOfAnotherRendererUnlessForced) {
    const auto dir = scratch_dir();
    const auto goldens = copy_goldens(dir);
    nlohmann::json record = nlohmann::json::parse(read_text(goldens / "golden-renderers.json"));
    record["images"]["default_0150.png"]["gl_version"] = "9.9 another Mesa";
    write_text(goldens / "golden-renderers.json", record.dump(2));
    paint_square(goldens / "default_0150.png", 10, 10, 20);
    const std::string painted = read_text(goldens / "default_0150.png");
    CliResult r = run_tumble(dir, "test goldens/suite.json --filter 'default_0*'");
    EXPECT_EQ(r.exit_code, 1);
    // Reported per check: only the golden from the other renderer says so.
    EXPECT_TRUE(contains(r.out, "the golden was drawn by \"llvmpipe")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"9.9 another Mesa\"; this machine has")) << r.out;
    EXPECT_EQ(r.out.find("drawn by"), r.out.rfind("drawn by")) << r.out;
    r = run_tumble(dir, "test goldens/suite.json --filter 'default_0*' --update");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_TRUE(contains(r.err, "default_0150; pass --force")) << r.err;
    EXPECT_EQ(read_text(goldens / "default_0150.png"), painted);
    r = run_tumble(dir, "test goldens/suite.json --filter 'default_0*' --update --force");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "updated goldens/default_0150.png (was: ")) << r.out;
    EXPECT_FALSE(contains(read_text(goldens / "golden-renderers.json"), "another"));
    EXPECT_EQ(run_tumble(dir, "test goldens/suite.json --filter 'default_0*'").exit_code, 0);
}

TEST(RegressionSuite, ASelectionOfNoCheckIsBadInput) {
    const auto dir = scratch_dir();
    copy_goldens(dir);
    CliResult r = run_tumble(dir, "test goldens/suite.json --filter 'nothing*'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "--filter 'nothing*' selects no check")) << r.err;
    // One filter of two selecting nothing is a typo, not a smaller run.
    r = run_tumble(dir, "test goldens/suite.json --filter default_0000 --filter defualt_0150");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "--filter defualt_0150 selects no check")) << r.err;
    r = run_tumble(dir, "test --filter 'tossed_book_00[0-9]0' goldens/suite.json"); // either order
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "2 checks: 2 passed")) << r.out; // frames 0 and 90
}

// A golden trajectory is what `tumble simulate` writes: a whole run passes a state check.
TEST(RegressionSuite, AStateGoldenMayBeAWholeSimulateRun) {
    const auto dir = scratch_dir();
    write_text(dir / "suite.json", R"({"format_version": 1, "scenes": [{"scene": "tossed_book",
        "states": [{"bodies": ["book"], "times": [0.5, 1, 2.5],
                    "quantities": {"position": 0, "orientation": 0, "velocity": 0,
                                   "angular_velocity": 0, "energy": 0, "momentum": 0,
                                   "angular_momentum": 0}}]}]})");
    ASSERT_EQ(run_tumble(dir, "simulate tossed_book -o tossed_book_states.csv -q").exit_code, 0);
    const CliResult r = run_tumble(dir, "test suite.json");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "ok     tossed_book_states: 3 samples, 7 series within")) << r.out;
}

TEST(RegressionSuite, MasksIgnoreTheirRectanglesAndNothingElse) {
    const auto dir = scratch_dir();
    const auto suite = [](const char* mask) {
        return std::string(R"({"format_version": 1, "scenes": [{"scene": "tossed_book",
            "images": [{"frames": [0], "masks": [)") +
               mask + "]}]}]}";
    };
    write_text(dir / "suite.json", suite(""));
    ASSERT_EQ(run_tumble(dir, "test suite.json --update").exit_code, 0);
    paint_square(dir / "tossed_book_0000.png", 100, 50, 12);
    EXPECT_EQ(run_tumble(dir, "test suite.json").exit_code, 1);
    write_text(dir / "suite.json", suite(R"({"x": 98, "y": 48, "width": 16, "height": 16})"));
    CliResult r = run_tumble(dir, "test suite.json");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "1 masked rectangle(s) ignored")) << r.out;
    // A mask one pixel short of the square leaves a column of it to be seen.
    write_text(dir / "suite.json", suite(R"({"x": 100, "y": 50, "width": 11, "height": 12})"));
    r = run_tumble(dir, "test suite.json");
    EXPECT_EQ(r.exit_code, 1) << r.out;
}

TEST(RegressionSuite, ASceneWhoseRunDivergesFailsItsChecksAndExitsOne) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", R"({"format_version": 1,
        "world": {"duration": 20, "dt": 0.2, "gravity": [0, 0, 0], "integrator": "euler"},
        "render": {"fps": 5},
        "bodies": [{"name": "book", "shape": {"type": "box", "size": [0.3, 0.2, 0.04]},
                    "angular_velocity": [0.02, 8, 0.02]}]})");
    write_text(dir / "suite.json", R"({"format_version": 1, "scenes": [
        {"scene": "s.json", "images": [{"frames": [0, 50]}],
         "states": [{"every": 10, "quantities": {"energy": 1}}]},
        {"scene": "tossed_book", "states": [{"frames": [0], "quantities": {"energy": 0}}]}]})");
    const CliResult r = run_tumble(dir, "test suite.json --update");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "FAIL   s_0000: the run failed: s.json: body 0 \"book\"")) << r.out;
    EXPECT_TRUE(contains(r.out, "cannot update s_states: the run failed")) << r.out;
    EXPECT_TRUE(contains(r.out, "added   tossed_book_states.csv")) << r.out; // the rest ran
}

// Ctrl-C stops after the scenes running and writes nothing: no half-updated goldens, no report
// of a partial run.
TEST(RegressionSuite, CtrlCStopsTheRunAndWritesNothing) {
    const auto dir = scratch_dir();
    write_text(dir / "suite.json", R"({"format_version": 1, "scenes": [
        {"scene": "sphere_rain", "images": [{"frames": [299]}]},
        {"scene": "sphere_columns", "images": [{"frames": [299]}]},
        {"scene": "tossed_book", "states": [{"frames": [0], "quantities": {"energy": 0}}]}]})");
    const pid_t pid =
        start_tumble(dir, "test suite.json --update --junit j.xml --report rep > out.txt");
    const ChildGuard child{pid};
    ASSERT_TRUE(wait_until_said(dir / "out.txt", "3 of 3 checks, 1 job(s)"));
    kill(pid, SIGINT);
    EXPECT_EQ(wait_for_exit(pid), 130);
    // Said by the handler, not the default action (which exits 130 too); how many checks ran
    // depends on when the signal landed, never all of them.
    const std::string err = read_text(dir / "stderr.txt");
    EXPECT_TRUE(contains(err, "test interrupted after ")) << err;
    EXPECT_FALSE(contains(err, "after 3 of 3")) << err;
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"out.txt", "stderr.txt", "suite.json"}));
}

} // namespace
} // namespace tumble::test
