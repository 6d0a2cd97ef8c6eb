// Every named integrator runs from the command line on a scene, and `tumble explain` says which
// step stages are on and why.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

namespace tumble::test {
namespace {

const char* const kIntegrators[] = {"euler", "euler_momentum",  "symplectic_euler", "implicit_gyro",
                                    "rk4",   "splitting",       "midpoint",         "splitting4",
                                    "exact", "splitting_exact", "splitting4_exact"};

TEST(IntegratorsCli, EveryIntegratorSimulatesTheDefaultScene) {
    for (const char* name : kIntegrators) {
        SCOPED_TRACE(name);
        const auto dir = scratch_dir() / name;
        std::filesystem::create_directories(dir);
        const CliResult r = run_tumble(
            dir, std::string("simulate --quiet --duration 0.5 --integrator ") + name + " -o s.csv");
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(files_in(dir), (std::vector<std::string>{"s.csv", "s.diagnostics.csv"}));
    }
}

TEST(IntegratorsCli, ExplainSaysWhichStagesAreOnAndWhy) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "explain default --integrator splitting");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The default scene: a floating book (gravity_scale 0) and three balls that fall.
    EXPECT_NE(r.out.find("gravity        on: 3 of 4 dynamic bodies"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("applied loads  off"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("gyroscopic     on: 1 of 4 dynamic bodies have unequal moments (the "
                         "isotropic skip it"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("integrate      splitting (order 2)"), std::string::npos) << r.out;
    // The ground and a falling ball can touch: the reason, the substeps and sleeping, in numbers.
    EXPECT_NE(r.out.find("contacts       on: bodies 0 and 2 accelerate relative to each other "
                         "(9.81 m/s^2)"),
              std::string::npos)
        << r.out;
    // Effort on demand (issue 28), and what it spent over the first second: a ball alone
    // on the ground sags m g / (m omega^2) = g / (2 * 2 pi (1/4) n / h)^2 = 0.017 mm at n = 1
    // (h = 1/240 s), within the 0.1 mm tolerance: one substep; a sphere's manifold has one point,
    // so one solve and one relax sweep.
    EXPECT_NE(r.out.find("effort on demand: each island of bodies in contact gets the substeps "
                         "that keep its contacts' sag within the contact tolerance 0.1 mm"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("substeps per island 1..1 (1 per body in contact), 2 sweeps per contact "
                         "point per step"),
              std::string::npos)
        << r.out;
}

TEST(IntegratorsCli, ExactRefusesAnAppliedTorqueNamingTheBodyAndField) {
    // Chosen on the command line or in the file: exit 2 before anything is written, naming the
    // file, the JSON path and the body by name, and pointing at the integrator that takes torques.
    const auto dir = scratch_dir();
    const std::string bodies =
        R"("bodies": [{"name": "free", "shape": {"type": "sphere", "radius": 0.1}},
                      {"name": "spinner", "position": [1, 0, 0],
                       "shape": {"type": "box", "size": [0.2, 0.1, 0.3]},
                       "angular_velocity": [1, 2, 3], "torque": [0, 0.1, 0]}]})";
    write_text(dir / "rk4.json",
               R"({"format_version": 1, "world": {"gravity": [0, 0, 0], "integrator": "rk4"}, )" +
                   bodies);
    write_text(dir / "exact.json",
               R"({"format_version": 1, "world": {"gravity": [0, 0, 0], "integrator": "exact"}, )" +
                   bodies);
    const std::string expected = ": /bodies/1/torque: body 1 \"spinner\" has an applied torque "
                                 "(0, 0.1, 0) N m, but the `exact` integrator steps torque-free "
                                 "bodies only; use `splitting_exact`";
    const CliResult cli = run_tumble(dir, "simulate rk4.json --quiet --integrator exact -o s.csv");
    EXPECT_EQ(cli.exit_code, 2) << cli.err;
    EXPECT_NE(cli.err.find("rk4.json" + expected), std::string::npos) << cli.err;
    const CliResult file = run_tumble(dir, "simulate exact.json --quiet -o s.csv");
    EXPECT_EQ(file.exit_code, 2) << file.err;
    EXPECT_NE(file.err.find("exact.json" + expected), std::string::npos) << file.err;
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"exact.json", "rk4.json"}));
    const CliResult ok =
        run_tumble(dir, "simulate rk4.json --quiet --integrator splitting_exact -o s.csv");
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    const CliResult explain = run_tumble(dir, "explain default --integrator exact");
    EXPECT_NE(explain.out.find("integrate      exact (exact: no truncation error)"),
              std::string::npos)
        << explain.out;
}

} // namespace
} // namespace tumble::test
