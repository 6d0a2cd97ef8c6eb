// What `-o X` does when X is not a plain new file (io/output_target.h): "-" and /dev/stdout
// stream to standard output, a FIFO is written in place, a symlink to a regular file is followed,
// and a device or directory is refused (exit 2) and left exactly as it was. Devices are reached
// through symlinks in the scratch folder, so a regression replaces a symlink, never /dev/full.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <thread>

namespace tumble::test {
namespace {

namespace fs = std::filesystem;

const std::string kRun = "simulate default --duration 0.05 -q";

std::string symlink_target(const fs::path& p) {
    return fs::is_symlink(p) ? fs::read_symlink(p).string() : "(not a symlink)";
}

// The bytes a run writes to a regular file: what every other kind of output must receive too.
std::string reference_states(const fs::path& dir) {
    const CliResult r = run_tumble(dir, kRun + " -o ref.csv --diagnostics none");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::string text = read_text(dir / "ref.csv");
    // The scene's record, then the header (app/run/trajectory_rows.h).
    EXPECT_TRUE(text.starts_with("# tumble scene {")) << text.substr(0, 80);
    EXPECT_NE(text.find("\nstep,t,body,"), std::string::npos) << text.substr(0, 160);
    fs::remove(dir / "ref.csv");
    return text;
}

TEST(OutputKinds, DashAndDevStdoutStreamTheStatesToStandardOutput) {
    const auto dir = scratch_dir();
    const std::string states = reference_states(dir);
    for (const std::string out : {"-", "/dev/stdout"}) {
        SCOPED_TRACE(out);
        const CliResult r = run_tumble(dir, kRun + " -o " + out + " --diagnostics none");
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(r.out, states);
        EXPECT_TRUE(files_in(dir).empty()) << "wrote a file: " << files_in(dir).front();
    }
    EXPECT_TRUE(fs::is_symlink("/dev/stdout")); // not replaced by a regular file
    // A symlink of the user's own to /proc/self/fd/1 is standard output just the same.
    fs::create_symlink("/proc/self/fd/1", dir / "out");
    const CliResult r = run_tumble(dir, kRun + " -o out --diagnostics none");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, states);
    EXPECT_EQ(symlink_target(dir / "out"), "/proc/self/fd/1");
}

TEST(OutputKinds, DiagnosticsOfAStreamGoOnlyWhereAsked) {
    const auto dir = scratch_dir();
    CliResult r = run_tumble(dir, "simulate default --duration 0.05 -o -");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("diagnostics are written only with --diagnostics"), std::string::npos)
        << r.err;
    r = run_tumble(dir, kRun + " -o - --diagnostics d.csv");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(read_text(dir / "d.csv").starts_with("step,t,kinetic,potential,energy"));
    r = run_tumble(dir, kRun + " -o - --diagnostics -");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("two tables cannot share one output"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
}

TEST(OutputKinds, AFifoIsWrittenInPlaceAndStaysAFifo) {
    const auto dir = scratch_dir();
    const std::string states = reference_states(dir);
    ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = read_text(dir / "pipe"); }); // blocks until opened
    const CliResult r = run_tumble(dir, kRun + " -o pipe --diagnostics none");
    reader.join();
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(received, states);
    struct stat st {};
    ASSERT_EQ(lstat((dir / "pipe").c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(OutputKinds, ASymlinkToARegularFileIsFollowed) {
    const auto dir = scratch_dir();
    const std::string states = reference_states(dir);
    write_text(dir / "real.csv", "old\n");
    fs::create_symlink("real.csv", dir / "link.csv");
    const CliResult r = run_tumble(dir, kRun + " -o link.csv --diagnostics none");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(symlink_target(dir / "link.csv"), "real.csv");
    EXPECT_EQ(read_text(dir / "real.csv"), states);
}

TEST(OutputKinds, DevicesAndDirectoriesAreRefusedAndLeftAsTheyWere) {
    const auto dir = scratch_dir();
    fs::create_symlink("/dev/full", dir / "full.csv");
    fs::create_symlink("/dev/null", dir / "null.png");
    fs::create_directory(dir / "folder.csv");
    struct Case {
        std::string args, named, kind;
    };
    for (const Case& c : std::vector<Case>{
             {kRun + " -o full.csv", "full.csv", "a character device"},
             {"render --frame 0 --width 64 --height 48 -o null.png -q", "null.png",
              "a character device"},
             {kRun + " -o folder.csv", "folder.csv", "a directory"},
         }) {
        SCOPED_TRACE(c.args);
        const CliResult r = run_tumble(dir, c.args);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find("cannot write to '" + c.named + "': it is " + c.kind),
                  std::string::npos)
            << r.err;
    }
    EXPECT_EQ(symlink_target(dir / "full.csv"), "/dev/full");
    EXPECT_EQ(symlink_target(dir / "null.png"), "/dev/null");
    EXPECT_TRUE(fs::is_directory(dir / "folder.csv"));
    EXPECT_TRUE(fs::is_empty(dir / "folder.csv"));
    for (const std::string& f : files_in(dir)) ADD_FAILURE() << "left behind: " << f;
}

} // namespace
} // namespace tumble::test
