// `--tolerance` and world.integrator "auto" as a user runs them: the run says what it chose, meets
// the tolerance against the exact Jacobi motion (physics/exact, computed here from the scene's
// initial state; the planner never reads it), and bad tolerances exit 2 naming the place.
#include "app/run/simulation.h"
#include "app/scene/scene.h"
#include "physics/exact/body_motion.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace tumble::test {
namespace {

// Largest angle (rad) between the book's orientation in a states CSV and its exact motion.
double worst_orientation_error(const std::string& csv, const std::string& scene_name) {
    const app::Scene scene = app::load_scene_argument(scene_name);
    const app::Simulation sim = app::make_simulation(scene, scene.world.dt);
    const int book = sim.model.dynamic_bodies.front();
    const exact::ExactBodyMotion oracle(sim.model, sim.state, book);
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line); // the scene's record: # tumble scene {...}
    std::getline(in, line); // header: step,t,body,name,x,y,z,qw,qx,qy,qz,...
    double worst = 0.0;
    int rows = 0;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream s(line);
        for (std::string cell; std::getline(s, cell, ',');) f.push_back(cell);
        if (std::stoi(f[2]) != book) continue;
        const physics::Quat q(std::stod(f[7]), std::stod(f[8]), std::stod(f[9]), std::stod(f[10]));
        // The CSV holds the body frame; the oracle the mass frame (q_mass = q_body body_from_mass).
        const physics::Quat ref =
            oracle.at(std::stod(f[1])).q * sim.model.body_from_mass[book].inverse();
        worst = std::max(worst, q.angularDistance(ref));
        ++rows;
    }
    EXPECT_GT(rows, 100);
    return worst;
}

TEST(AccuracyCli, ToleranceIsMetAgainstTheExactMotionAndTheRunSaysSo) {
    const auto dir = scratch_dir();
    const CliResult r =
        run_tumble(dir, "simulate lessons/intermediate_axis --tolerance 1e-4 -o s.csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("tumble: auto: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("tolerance 0.0001 rad / 0.0001 m met"), std::string::npos) << r.err;
    // 12 s, four flips: measured 4.77e-5 rad with splitting at 4 steps per frame (the estimate said
    // 4.8e-5).
    EXPECT_LE(worst_orientation_error(read_text(dir / "s.csv"), "lessons/intermediate_axis"), 1e-4);
}

TEST(AccuracyCli, RenderChoosesAsSimulateDoes) {
    const auto dir = scratch_dir();
    const std::string opts = " lessons/intermediate_axis --tolerance 1e-5 --duration 3";
    const CliResult sim = run_tumble(dir, "simulate" + opts + " -o s.csv");
    const CliResult video =
        run_tumble(dir, "render" + opts + " --width 160 --height 96 -o v.mp4 --quiet");
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    ASSERT_EQ(video.exit_code, 0) << video.err;
    const auto choice = [](const std::string& err) {
        const std::size_t a = err.find("auto: ");
        return a == std::string::npos ? std::string{} : err.substr(a, err.find(';', a) - a);
    };
    EXPECT_FALSE(choice(sim.err).empty());
    const CliResult loud = run_tumble(dir, "render" + opts + " --width 160 --height 96 -o w.mp4");
    EXPECT_EQ(choice(loud.err), choice(sim.err)) << loud.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "v.mp4"));
}

TEST(AccuracyCli, ANamedIntegratorIsCheckedAndWarnsWhenItMisses) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "simulate lessons/intermediate_axis --integrator euler "
                                        "--tolerance 1e-6 --duration 2 -o s.csv");
    ASSERT_EQ(r.exit_code, 0) << r.err; // a warning, not a failure
    EXPECT_NE(r.err.find("warning: body 1 \"book\": estimated error"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("exceeds the tolerance"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("auto: "), std::string::npos) << r.err;
}

TEST(AccuracyCli, BadTolerancesExit2NamingThePlace) {
    const auto dir = scratch_dir();
    for (const char* bad : {"abc", "0", "-1e-3", "1e-4,x", "1e-4,"}) {
        const CliResult r =
            run_tumble(dir, std::string("explain lessons/intermediate_axis --tolerance=") + bad);
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_NE(r.err.find("--tolerance " + std::string(bad) + ": expected a positive"),
                  std::string::npos)
            << r.err;
    }
    write_text(dir / "no_tol.json",
               R"({"format_version": 1, "world": {"integrator": "auto", "gravity": [0, 0, 0]},
                   "bodies": [{"shape": {"type": "sphere", "radius": 0.1}, "mass": 1}]})");
    CliResult r = run_tumble(dir, "explain no_tol.json");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no_tol.json: /world: world.integrator \"auto\" needs world.tolerance"),
              std::string::npos)
        << r.err;
    write_text(dir / "neg.json",
               R"({"format_version": 1, "world": {"integrator": "auto", "tolerance":
                   {"rotation": -1, "position": 1e-3}}, "bodies": []})");
    r = run_tumble(dir, "explain neg.json");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("neg.json: /world/tolerance/rotation"), std::string::npos) << r.err;
    r = run_tumble(dir, "simulate lessons/intermediate_axis --tolerance 1e-4 --no-error-estimate "
                        "-o s.csv");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--no-error-estimate: the tolerance (--tolerance)"), std::string::npos)
        << r.err;
}

} // namespace
} // namespace tumble::test
