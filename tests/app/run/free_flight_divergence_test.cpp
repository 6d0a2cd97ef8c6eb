// A body that diverges in free flight (no contact, no integrator instability: a speed whose
// kinetic energy overflows a double) is a failed run, exit 1, from `simulate` and `render`, the
// message naming the scene file, the body as the scene names it, the quantity and the step.
#include "support/bad_input_case.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

namespace tumble::test {
namespace {

const char* kRocket = R"({
  "format_version": 1,
  "world": {"duration": 0.5, "gravity": [0, 0, 0]},
  "render": {"width": 64, "height": 48, "fps": 10},
  "bodies": [{"name": "rocket", "shape": {"type": "sphere", "radius": 0.1},
              "velocity": [1, 0, 0]}]
})";

void expect_failed_run(const std::string& scene, const std::string& quantity) {
    for (const char* cmd : {"simulate s.json -o states.csv", "render s.json -o out.mp4",
                            "render s.json -o frames/"}) {
        SCOPED_TRACE(cmd);
        const auto dir = scratch_dir();
        write_text(dir / "s.json", scene);
        const CliResult r = run_tumble(dir, cmd);
        EXPECT_EQ(r.exit_code, 1) << r.err;
        for (const std::string& s :
             {std::string("s.json: body 0 \"rocket\": "), quantity, std::string("after step 1 ")})
            EXPECT_NE(r.err.find(s), std::string::npos) << s << "\n" << r.err;
        EXPECT_EQ(files_in(dir), std::vector<std::string>{"s.json"});
    }
}

TEST(FreeFlightDivergence, ASpeedOf1e160IsAFailedRunNamingTheBody) {
    expect_failed_run(replace(kRocket, "\"velocity\": [1, 0, 0]", "\"velocity\": [1e160, 0, 0]"),
                      "kinetic energy m |v|^2 is not finite");
}

TEST(FreeFlightDivergence, AnAngularSpeedOf1e160IsAFailedRunNamingTheBody) {
    // Explicit Euler keeps the orientation finite at any finite w (rk4's update does not).
    std::string scene =
        replace(kRocket, "\"velocity\": [1, 0, 0]", "\"angular_velocity\": [0, 0, 1e160]");
    expect_failed_run(
        replace(scene, "\"duration\": 0.5", "\"duration\": 0.5, \"integrator\": \"euler\""),
        "rotational kinetic energy I |w|^2 is not finite");
}

TEST(FreeFlightDivergence, TheSameSceneAtAModestSpeedRuns) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kRocket);
    EXPECT_EQ(run_tumble(dir, "simulate s.json -o states.csv -q").exit_code, 0);
}

} // namespace
} // namespace tumble::test
