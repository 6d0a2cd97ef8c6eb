// Scene input of the contact pipeline through the real binary: every kind of bad contact input
// exits 2 with a message naming the file, the JSON path and what was expected, leaving nothing
// behind; bodies starting deeply interpenetrated get a warning naming the pair; and physics
// threads change nothing in the output.
#include "render/png_io.h"
#include "support/bad_input_case.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace tumble::test {
namespace {

// A valid contact scene; each case below breaks one thing in it.
const char* kGood = R"({
  "format_version": 1,
  "world": {"duration": 0.1, "sleeping": true, "substeps": 0, "restitution_threshold": 0.5},
  "render": {"width": 64, "height": 48, "fps": 10},
  "bodies": [
    {"name": "floor", "shape": {"type": "plane"}},
    {"name": "pill", "shape": {"type": "capsule", "radius": 0.1, "length": 0.3},
     "position": [0, 0, 0.5], "material": {"friction": 0.5, "restitution": 0.3}},
    {"name": "left wall", "shape": {"type": "box", "size": [0.1, 2, 1]}, "static": true,
     "position": [-1, 0, 0.5]},
    {"name": "right wall", "shape": {"type": "box", "size": [0.1, 2, 1]}, "static": true,
     "position": [1, 0, 0.5]},
    {"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "position": [0.5, 0, 0.5]}
  ]
})";

// Two faces of a tetrahedron are missing: not a closed surface.
const char* kOpenObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n";

std::vector<Case> cases() {
    const std::string pill = R"({"type": "capsule", "radius": 0.1, "length": 0.3})";
    const std::string ball = R"({"type": "sphere", "radius": 0.1})";
    return {
        {"negative_friction",
         replace(kGood, "\"friction\": 0.5", "\"friction\": -0.1"),
         {"/bodies/1/material/friction", "friction coefficient >= 0"}},
        {"restitution_above_one",
         replace(kGood, "\"restitution\": 0.3", "\"restitution\": 1.5"),
         {"/bodies/1/material/restitution", "restitution in [0, 1]"}},
        {"zero_capsule_radius",
         replace(kGood, pill, R"({"type": "capsule", "radius": 0, "length": 0.3})"),
         {"/bodies/1/shape/radius", "positive capsule radius"}},
        {"negative_capsule_length",
         replace(kGood, pill, R"({"type": "capsule", "radius": 0.1, "length": -0.3})"),
         {"/bodies/1/shape/length", "positive length"}},
        {"capsule_half_length_is_not_a_field",
         replace(kGood, pill, R"({"type": "capsule", "radius": 0.1, "half_length": 0.3})"),
         {"/bodies/1/shape", "missing required field \"length\""}},
        {"zero_sphere_radius",
         replace(kGood, ball, R"({"type": "sphere", "radius": 0})"),
         {"/bodies/4/shape/radius", "positive radius"}},
        {"flat_box",
         replace(kGood, "\"size\": [0.1, 2, 1]", "\"size\": [0.1, 0, 1]"),
         {"/bodies/2/shape/size", "positive box edge lengths"}},
        {"overlapping_static_boxes",
         replace(kGood, "\"position\": [1, 0, 0.5]", "\"position\": [-0.95, 0, 0.5]"),
         {"/bodies/3/position", "\"right wall\"", "\"left wall\"", "overlaps"}},
        {"substeps_out_of_range",
         replace(kGood, "\"substeps\": 0", "\"substeps\": 65"),
         {"/world/substeps", "contact substeps per step"}},
        {"negative_iterations", // 0 is effort on demand (issue 28)
         replace(kGood, "\"substeps\": 0", "\"substeps\": 0, \"iterations\": -1"),
         {"/world/iterations", "contact solve sweeps per substep, 1..64"}},
        {"zero_contact_tolerance",
         replace(kGood, "\"substeps\": 0", "\"substeps\": 0, \"contact_tolerance\": 0"),
         {"/world/contact_tolerance", "the largest contact sag"}},
        {"negative_restitution_threshold",
         replace(kGood, "\"restitution_threshold\": 0.5", "\"restitution_threshold\": -1"),
         {"/world/restitution_threshold", "impact speed >= 0"}},
        {"sleeping_not_a_switch",
         replace(kGood, "\"sleeping\": true", "\"sleeping\": \"yes\""),
         {"/world/sleeping", "true or false"}},
        {"missing_mesh_file",
         replace(kGood, ball, R"({"type": "mesh", "file": "nowhere.obj"})"),
         {"/bodies/4/shape/file", "no mesh file \"nowhere.obj\""}},
        {"open_mesh",
         replace(kGood, ball, R"({"type": "mesh", "file": "open.obj"})"),
         {"/bodies/4/shape/file", "open.obj", "closed"}},
        {"zero_mesh_scale",
         replace(kGood, ball, R"({"type": "mesh", "file": "top.obj", "scale": 0})"),
         {"/bodies/4/shape/scale", "positive scale"}},
    };
}

TEST(ContactInput, EveryKindOfBadContactInputExitsTwoWithItsPlaceAndNoOutput) {
    for (const Case& c : cases()) expect_refused(c, "bad.json: /", {{"open.obj", kOpenObj}});
}

TEST(ContactInput, TheValidSceneRunsWithoutWarnings) {
    const auto dir = scratch_dir();
    write_text(dir / "good.json", kGood);
    const CliResult r = run_tumble(dir, "simulate good.json -o states.csv");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

TEST(ContactInput, DeeplyInterpenetratedBodiesGetAWarningNamingThePairAndTheRunGoesOn) {
    const auto dir = scratch_dir();
    // The ball's centre 0.25 m from the capsule's axis: 5 cm deep in it.
    write_text(dir / "deep.json",
               replace(kGood, "\"position\": [0.5, 0, 0.5]", "\"position\": [0.15, 0, 0.5]"));
    const CliResult r = run_tumble(dir, "simulate deep.json -o states.csv");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: deep.json: /bodies/4/position"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("body 4 \"ball\" starts interpenetrating body 1 \"pill\" by 50.0 mm"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "states.csv"));
}

// A pile: 24 boxes and spheres dropped in a loose heap into a walled pen, so that the contact
// stage has hundreds of contacts to split between threads.
std::string pile_scene() {
    std::string bodies = R"({"shape": {"type": "plane"}})";
    for (int side : {-1, 1}) {
        bodies += R"(, {"shape": {"type": "box", "size": [0.1, 1.2, 0.5]}, "static": true,)"
                  R"( "position": [)" +
                  std::to_string(side * 0.55) + ", 0, 0.25]}";
    }
    for (int i = 0; i < 24; ++i) {
        const double x = 0.17 * (i % 4) - 0.25, y = 0.17 * ((i / 4) % 2) - 0.08;
        const double z = 0.15 + 0.17 * (i / 8);
        const std::string shape = i % 3 ? R"({"type": "box", "size": [0.12, 0.1, 0.08]})"
                                        : R"({"type": "sphere", "radius": 0.06})";
        bodies += R"(, {"shape": )" + shape + R"(, "position": [)" + std::to_string(x) + ", " +
                  std::to_string(y) + ", " + std::to_string(z) + "], \"angular_velocity\": [" +
                  std::to_string(0.3 * (i % 5)) + ", 1, 0]}";
    }
    return R"({"format_version": 1, "world": {"duration": 1.5, "sleeping": false,)"
           R"( "parallel_min_bodies": 0},)"
           R"( "bodies": [)" +
           bodies + "]}";
}

// Asking for threads a scene will not use is said, with the reason and the way round it.
TEST(ContactInput, UnusedThreadsAreReported) {
    const auto dir = scratch_dir();
    std::string pile = pile_scene();
    const std::string forced = R"("parallel_min_bodies": 0)";
    write_text(dir / "pile.json", pile);
    pile.replace(pile.find(forced), forced.size(), R"("parallel_min_bodies": 100)");
    write_text(dir / "small.json", pile);
    write_text(dir / "free.json", R"({"format_version": 1, "world": {"duration": 0.1},)"
                                  R"( "bodies": [{"shape": {"type": "box", "size": [1, 2, 3]}}]})");
    const CliResult small = run_tumble(dir, "simulate small.json --threads 2 -o s.csv");
    ASSERT_EQ(small.exit_code, 0) << small.err;
    EXPECT_NE(small.err.find("--threads 2 not used: the scene has 24 dynamic bodies, fewer than "
                             "world.parallel_min_bodies (100)"),
              std::string::npos)
        << small.err;
    const CliResult free = run_tumble(dir, "simulate free.json --threads 2 -o f.csv");
    ASSERT_EQ(free.exit_code, 0) << free.err;
    EXPECT_NE(free.err.find("--threads 2 not used: the scene has no contact stage"),
              std::string::npos)
        << free.err;
    const CliResult used = run_tumble(dir, "simulate pile.json --threads 2 -o p.csv");
    ASSERT_EQ(used.exit_code, 0) << used.err;
    EXPECT_EQ(used.err.find("not used"), std::string::npos) << used.err;
}

// Threads split the contact stage's work into fixed ranges: the states must be the same bits for
// 1, 2, 3 and 4 threads (even and uneven splits, and more workers than the machine's 2 cores).
TEST(ContactInput, SimulateGivesIdenticalStatesForOneToFourPhysicsThreads) {
    const auto dir = scratch_dir();
    write_text(dir / "pile.json", pile_scene());
    const char* common = "simulate pile.json --every 12 -q";
    std::vector<std::string> csv;
    for (int threads = 1; threads <= 4; ++threads) {
        const std::string out = std::to_string(threads) + ".csv";
        ASSERT_EQ(run_tumble(dir, std::string(common) + " --threads " + std::to_string(threads) +
                                      " -o " + out)
                      .exit_code,
                  0);
        csv.push_back(read_text(dir / out));
    }
    const std::string& one = csv[0];
    EXPECT_GT(one.size(), 20000u);                 // 27 bodies x 31 rows
    for (int threads = 2; threads <= 4; ++threads) // %.17g: equal text = equal bits
        EXPECT_TRUE(csv[std::size_t(threads - 1)] == one) << threads << " threads differ from 1";
    // The pile moved: the top body's state in the last row (body 26 at the last step) differs
    // from its first row.
    const std::string tag = "\"body 26\",";
    const auto first = one.find(tag), last = one.rfind(tag);
    ASSERT_NE(first, std::string::npos);
    ASSERT_NE(first, last);
    EXPECT_NE(one.substr(first, one.find('\n', first) - first),
              one.substr(last, one.find('\n', last) - last));
}

// The frames a user renders are the same pixels for 1, 2, 3 and 4 physics threads (PNG frames,
// compared as decoded pixels), and the pile moves in them.
TEST(ContactInput, RenderGivesIdenticalFramesForOneToFourPhysicsThreads) {
    const auto dir = scratch_dir();
    write_text(dir / "pile.json", pile_scene());
    std::vector<std::vector<render::Image>> runs;
    for (int threads = 1; threads <= 4; ++threads) {
        const std::string out = std::to_string(threads) + "threads/";
        const CliResult r = run_tumble(dir, "render pile.json --duration 1 --fps 10 --width 160 "
                                            "--height 90 -q --threads " +
                                                std::to_string(threads) + " -o " + out);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        std::vector<render::Image> frames;
        for (int k = 0; k < 10; ++k) {
            char name[16];
            std::snprintf(name, sizeof name, "%06d.png", k);
            frames.push_back(render::read_png(dir / out / name));
        }
        runs.push_back(std::move(frames));
    }
    for (std::size_t t = 1; t < runs.size(); ++t)
        for (std::size_t k = 0; k < runs[0].size(); ++k)
            EXPECT_TRUE(runs[t][k].rgb == runs[0][k].rgb)
                << "frame " << k << " with " << t + 1 << " threads differs from 1 thread";
    EXPECT_FALSE(runs[0].front().rgb == runs[0].back().rgb) << "the pile did not move";
}

TEST(ContactInput, ThreadCountOutsideItsRangeIsRefused) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "simulate --threads 0 -o states.csv");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
}

} // namespace
} // namespace tumble::test
