// One mapping of failures to exit codes for every subcommand (app/cli/failure.h, README "Exit
// codes"): bad input 2, a failed run 1, interrupted 128 + signal. Each class is provoked through
// each subcommand that can meet it, and each run must leave no output behind.
//
// A full disk is provoked with a file-size limit (ulimit -f, SIGXFSZ ignored): writes past it
// fail with EFBIG exactly as they do with ENOSPC. Not covered: `study` failing mid-run (its grid
// takes a minute before the first write) and `explain` and `scenes`, which run nothing that can
// fail but their input.
#include "support/cli_runner.h"
#include "support/interrupt_runner.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <thread>
#include <unistd.h>

namespace tumble::test {
namespace {

// A book spun at 8 rad/s: explicit Euler at dt = 0.2 s overflows its rotational kinetic energy
// (step 42; its angular velocity itself one step later).
const char* kDiverging = R"({
  "format_version": 1,
  "world": {"duration": 20, "dt": 0.2, "gravity": [0, 0, 0], "integrator": "euler"},
  "render": {"fps": 5},
  "bodies": [{"name": "book", "shape": {"type": "box", "size": [0.3, 0.2, 0.04]},
              "angular_velocity": [0.02, 8, 0.02]}]
})";

struct Case {
    const char* args;
    int exit_code;
    const char* message; // a part of stderr that says what went wrong
};

// Runs each case in a fresh folder holding s.json (the diverging scene); checks the exit code,
// the message, and that nothing but s.json is left.
void check_cases(const std::vector<Case>& cases, const std::string& prefix = "") {
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args);
        const auto dir = scratch_dir();
        write_text(dir / "s.json", kDiverging);
        const CliResult r = run_tumble(dir, prefix + c.args);
        EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("tumble: error: "), std::string::npos) << r.err;
        EXPECT_EQ(files_in(dir), std::vector<std::string>{"s.json"});
    }
}

TEST(ExitCodes, BadInputExitsTwoInEverySubcommand) {
    check_cases({
        {"render nosuch.json -o a.mp4", 2, "nosuch.json: file: no such file"},
        {"render s.json -o a.avi", 2, "unknown output type"},
        {"render s.json --frame 2 -o a.mp4", 2, "the output must end in .png"},
        {"render s.json --compare euler,nosuch -o a.mp4", 2, "unknown integrator"},
        {"simulate nosuch.json -o s.csv", 2, "nosuch.json: file: no such file"},
        // Missing parents are created (issue 14); a parent that is a file is bad input.
        {"simulate s.json -o s.json/deeper/s.csv", 2, "'s.json/deeper': Not a directory"},
        {"explain nosuch.json", 2, "nosuch.json: file: no such file"},
        {"explain s.json --dt -1", 2, "--dt"},
        {"test nosuch.json", 2, "nosuch.json"},
        {"test s.json", 2, "s.json: /: this is a scene file, not a suite"},
        {"diff nosuch.png other.png", 2, "nosuch.png"},
        {"study --quick -q -o s.json/study", 2, "'s.json/study': Not a directory"},
        {"plot nosuch.csv --quantity energy -o f.png", 2, "nosuch.diagnostics.csv: file: no such"},
        {"plot nosuch.csv --quantity w --bodies a -o f.pdf", 2, "ending in .png or .svg"},
    });
}

TEST(ExitCodes, ADivergedRunExitsOneNamingFileBodyAndStep) {
    check_cases({
        {"render s.json --width 64 --height 48 -o d.mp4", 1, "s.json: body 0 \"book\""},
        {"render s.json --width 64 --height 48 -o frames/", 1, "is not finite after step 42"},
        {"simulate s.json -o s.csv", 1, "s.json: body 0"},
    });
}

// A failed run keeps what was there: the output of an earlier, complete run survives a run to
// the same name that diverges or meets a full disk.
TEST(ExitCodes, AFailedRunLeavesAnExistingFileOfTheSameNameUntouched) {
    const auto dir = scratch_dir();
    write_text(dir / "s.json", kDiverging);
    const std::vector<std::string> outputs = {"d.mp4", "s.csv", "s.diagnostics.csv", "v.mp4"};
    for (const std::string& name : outputs) write_text(dir / name, "kept: " + name);
    for (const std::string& args : {
             std::string("\"$TUMBLE\" render s.json --width 64 --height 48 -o d.mp4 -q"),
             std::string("\"$TUMBLE\" simulate s.json -o s.csv -q"),
             std::string("trap '' XFSZ; ulimit -f 4; exec \"$TUMBLE\" render --duration 2 "
                         "--width 320 --height 180 -o v.mp4 -q"),
         }) {
        SCOPED_TRACE(args);
        EXPECT_EQ(run_shell(dir, args).exit_code, 1);
    }
    for (const std::string& name : outputs) EXPECT_EQ(read_text(dir / name), "kept: " + name);
    for (const std::string& f : files_in(dir))
        EXPECT_EQ(f.find(".partial"), std::string::npos) << f << " left behind";
}

TEST(ExitCodes, AFullDiskExitsOneInEverySubcommandThatWrites) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_tumble(dir, "render --frame 0 --width 320 --height 180 -o a.png -q").exit_code,
              0);
    ASSERT_EQ(run_tumble(dir, "render --frame 99 --width 320 --height 180 -o b.png -q").exit_code,
              0);
    ASSERT_EQ(run_tumble(dir, "simulate --duration 1 -o run.csv -q").exit_code, 0);
    write_text(dir / "suite.json", R"({"format_version": 1, "scenes": [{"scene": "tossed_book",
        "images": [{"frames": [0]}]}]})");
    // 4 blocks (2 KiB in dash's 512-byte blocks): far less than any of these outputs.
    const auto run_full = [&](const std::string& args) {
        return run_shell(dir, "trap '' XFSZ; ulimit -f 4; exec \"$TUMBLE\" " + args);
    };
    struct Full {
        const char* args;
        const char* leaves_no; // an output that must not exist afterwards
        const char* named;     // the message names the output as the user gave it
    };
    for (const Full& c : std::vector<Full>{
             {"render --duration 2 --width 320 --height 180 -o v.mp4 -q", "v.mp4", "'v.mp4'"},
             {"render --frame 0 --width 1280 --height 720 -o big.png -q", "big.png", "'big.png'"},
             {"simulate -o s.csv -q", "s.csv", "s.csv"},
             {"diff a.png b.png --max-different 0 -o d.png", "d.png", "'d.png'"},
             {"plot run.csv --quantity energy -q -o p.png", "p.png", "'p.png'"},
             {"test suite.json --report rep", "rep/index.html", "'rep/images/tossed_book_0000."},
             {"test suite.json --update", "tossed_book_0000.png", "'tossed_book_0000.png'"},
         }) {
        SCOPED_TRACE(c.args);
        const CliResult r = run_full(c.args);
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_NE(r.err.find("tumble: error: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.named), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find(".partial"), std::string::npos) << "names a temporary file: " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / c.leaves_no));
        for (const std::string& f : files_in(dir))
            EXPECT_EQ(f.find(".partial"), std::string::npos) << f << " left behind";
    }
}

TEST(ExitCodes, InterruptedRunsExitWith128PlusTheSignal) {
    auto dir = scratch_dir();
    EXPECT_EQ(interrupt_when_writing(dir, "simulate --duration 600 -o s.csv", ".s.csv", SIGTERM),
              143)
        << read_text(dir / "stderr.txt");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    EXPECT_EQ(interrupt_when_writing(dir,
                                     "render --compare euler,rk4 --duration 600 --width 160 "
                                     "--height 90 -o c.mp4",
                                     ".c.mp4", SIGINT),
              130)
        << read_text(dir / "stderr.txt");
    EXPECT_TRUE(std::filesystem::exists(dir / "c.mp4")); // finished so that it plays
}

} // namespace
} // namespace tumble::test
