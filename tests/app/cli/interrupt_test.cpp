// Interrupted and killed runs (README, "What Tumble promises"): SIGTERM finishes a video that
// plays; a second Ctrl-C quits at once and deletes what was in progress; a run killed outright
// leaves a temporary file that the next run of the same output removes, saying so; and an
// interrupted `simulate` keeps an existing complete file and stores the partial run apart.
#include "support/cli_runner.h"
#include "support/interrupt_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace tumble::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> partial_files(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().ends_with(".partial"))
            out.push_back(e.path().filename().string());
    return out;
}

TEST(Interrupts, SigtermFinishesAVideoThatPlays) {
    const auto dir = scratch_dir();
    EXPECT_EQ(interrupt_when_writing(dir, "render --duration 600 --width 160 --height 90 -o t.mp4",
                                     ".t.mp4", SIGTERM),
              143);
    const std::string err = read_text(dir / "stderr.txt");
    ASSERT_TRUE(fs::exists(dir / "t.mp4")) << err;
    const CliResult probe =
        run_shell(dir, "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                       "stream=nb_read_frames -of csv=p=0 t.mp4");
    EXPECT_EQ(probe.exit_code, 0) << probe.err;
    EXPECT_GT(std::atoi(probe.out.c_str()), 0) << probe.out;
    EXPECT_TRUE(partial_files(dir).empty());
}

// The first SIGINT asks the pipeline to finish the video, which at 1280x720 with shadows takes
// a while (the frames in flight are drawn and encoded first). The second, sent as soon as the
// first is acknowledged, must not wait for that: it exits 130 at once, deleting the temporary
// video, and leaves no video either.
TEST(Interrupts, ASecondCtrlCQuitsAtOnceAndDeletesTheOutputInProgress) {
    const auto dir = scratch_dir();
    const pid_t pid = start_tumble(dir, "render --duration 600 -o twice.mp4");
    const ChildGuard child{pid};
    ASSERT_TRUE(wait_until_writing(dir, ".twice.mp4"));
    kill(pid, SIGINT);
    EXPECT_TRUE(wait_until_said(dir / "stderr.txt", "again to quit at once"));
    kill(pid, SIGINT);
    EXPECT_EQ(wait_for_exit(pid), 130);
    const std::string err = read_text(dir / "stderr.txt");
    EXPECT_NE(err.find("interrupted again: stopped at once"), std::string::npos) << err;
    EXPECT_TRUE(partial_files(dir).empty()) << partial_files(dir).front();
    EXPECT_FALSE(fs::exists(dir / "twice.mp4"));
}

TEST(Interrupts, TheNextRunRemovesWhatAKilledRunLeftBehind) {
    const auto dir = scratch_dir();
    const pid_t pid = start_tumble(dir, "render --duration 600 --width 160 --height 90 -o k.mp4");
    const ChildGuard child{pid};
    ASSERT_TRUE(wait_until_writing(dir, ".k.mp4"));
    kill(pid, SIGKILL); // no handler runs: the temporary file stays
    EXPECT_EQ(wait_for_exit(pid), 128 + SIGKILL);
    const std::string left = ".k.mp4." + std::to_string(pid) + ".partial";
    ASSERT_EQ(partial_files(dir), std::vector<std::string>{left});
    write_text(dir / (".other.mp4." + std::to_string(pid) + ".partial"), "not ours");
    const CliResult r = run_tumble(dir, "render --duration 0.2 --width 160 --height 90 -o k.mp4");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("removed '" + left + "', left by process " + std::to_string(pid) +
                         ", no longer running"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(fs::exists(dir / "k.mp4"));
    // Another output's leftovers are not this run's business.
    EXPECT_EQ(partial_files(dir),
              std::vector<std::string>{".other.mp4." + std::to_string(pid) + ".partial"});
}

// The lines of a CSV but its comments (a states table's first line records its scene).
std::vector<std::string> lines_of(const fs::path& csv) {
    std::vector<std::string> out;
    std::ifstream in(csv);
    for (std::string line; std::getline(in, line);)
        if (!line.starts_with("#")) out.push_back(line);
    return out;
}

// Counts the data rows of a states CSV and returns the last row's step.
long long last_step(const fs::path& csv, int& rows) {
    const std::vector<std::string> lines = lines_of(csv);
    rows = lines.empty() ? 0 : static_cast<int>(lines.size()) - 1; // less the header
    return rows == 0 ? -1 : std::stoll(lines.back().substr(0, lines.back().find(',')));
}

TEST(Interrupts, AnInterruptedSimulateKeepsTheCompleteFileAndStoresThePartialRunApart) {
    const auto dir = scratch_dir();
    write_text(dir / "s.csv", "a complete run from before\n");
    write_text(dir / "s.diagnostics.csv", "its diagnostics\n");
    // 600 s at the default scene's step (1/240 s) is 144,000 steps: far more than can run before
    // the signal, which is sent once rows reach the temporary file.
    EXPECT_EQ(interrupt_when_writing(dir, "simulate --duration 600 -o s.csv", ".s.csv", SIGINT),
              130);
    const std::string err = read_text(dir / "stderr.txt");
    EXPECT_EQ(read_text(dir / "s.csv"), "a complete run from before\n");
    EXPECT_EQ(read_text(dir / "s.diagnostics.csv"), "its diagnostics\n");
    int rows = 0, diag_rows = 0;
    const long long step = last_step(dir / "s.interrupted.csv", rows);
    last_step(dir / "s.interrupted.diagnostics.csv", diag_rows);
    EXPECT_GT(step, 0) << err;
    EXPECT_LT(step, 144000);
    // One diagnostics row a step, and one states row per body a step (bodies: step 0's rows).
    const std::vector<std::string> lines = lines_of(dir / "s.interrupted.csv");
    const int bodies = static_cast<int>(std::count_if(
        lines.begin(), lines.end(), [](const std::string& l) { return l.starts_with("0,"); }));
    EXPECT_GT(bodies, 0);
    EXPECT_EQ(rows, diag_rows * bodies);
    EXPECT_NE(err.find("interrupted after " + std::to_string(step) + " steps"), std::string::npos)
        << err;
    EXPECT_NE(err.find("'s.csv' is as it was before"), std::string::npos) << err;
    EXPECT_TRUE(partial_files(dir).empty());
}

} // namespace
} // namespace tumble::test
