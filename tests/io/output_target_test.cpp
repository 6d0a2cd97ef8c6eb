// io/output_target.h and io/atomic_file.h: which outputs are replaced, streamed or refused, and
// that a commit never renames over something that became a device or pipe meanwhile.
#include "io/atomic_file.h"
#include "io/io_scratch.h"
#include "io/output_target.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sys/stat.h>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

TEST(OutputTarget, NewPathsAndRegularFilesAreReplaced) {
    const fs::path dir = fresh_dir();
    OutputTarget t = resolve_output(dir / "new.csv");
    EXPECT_EQ(t.kind, OutputKind::kReplace);
    EXPECT_EQ(t.path, dir / "new.csv");
    std::ofstream(dir / "old.csv") << "x";
    fs::create_symlink("old.csv", dir / "link.csv");
    t = resolve_output(dir / "link.csv");
    EXPECT_EQ(t.kind, OutputKind::kReplace);
    EXPECT_EQ(t.path, fs::canonical(dir / "old.csv")); // the target, not the link
    fs::create_symlink("not-yet.csv", dir / "dangling.csv");
    EXPECT_EQ(resolve_output(dir / "dangling.csv").path, fs::weakly_canonical(dir / "not-yet.csv"));
}

TEST(OutputTarget, FifosAndStandardOutputAreStreamed) {
    const fs::path dir = fresh_dir();
    ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0600), 0);
    OutputTarget t = resolve_output(dir / "pipe");
    EXPECT_EQ(t.kind, OutputKind::kStream);
    EXPECT_FALSE(t.standard_output);
    t = resolve_output("-");
    EXPECT_EQ(t.kind, OutputKind::kStream);
    EXPECT_TRUE(t.standard_output);
}

TEST(OutputTarget, DevicesDirectoriesAndUnreachablePathsAreRefused) {
    const fs::path dir = fresh_dir();
    fs::create_symlink("/dev/full", dir / "full");
    fs::create_symlink("loop-b", dir / "loop-a");
    fs::create_symlink("loop-a", dir / "loop-b");
    for (const auto& [path, why] : std::vector<std::pair<fs::path, std::string>>{
             {dir / "full", "it is a character device"},
             {dir, "it is a directory"},
             {dir / "loop-a", "Too many levels of symbolic links"},
         }) {
        SCOPED_TRACE(path);
        try {
            resolve_output(path);
            ADD_FAILURE() << "accepted";
        } catch (const OutputRefused& e) {
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
        }
    }
}

TEST(AtomicFile, AStreamIsWrittenInPlaceAndNeverRemoved) {
    const fs::path dir = fresh_dir();
    ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0600), 0);
    {
        AtomicFile f(dir / "pipe");
        EXPECT_TRUE(f.streaming());
        EXPECT_EQ(f.temp_path(), dir / "pipe");
        EXPECT_STREQ(f.fopen_mode(), "ab");
    } // discarded unused: a pipe must survive that
    struct stat st {};
    ASSERT_EQ(lstat((dir / "pipe").c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(AtomicFile, CommitRefusesADestinationThatBecameAFifoMeanwhile) {
    const fs::path dir = fresh_dir();
    AtomicFile f(dir / "out.csv");
    std::ofstream(f.temp_path()) << "contents";
    ASSERT_EQ(mkfifo((dir / "out.csv").c_str(), 0600), 0); // appears while the run writes
    EXPECT_THROW(f.commit(), FileError);
    struct stat st {};
    ASSERT_EQ(lstat((dir / "out.csv").c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    EXPECT_FALSE(fs::exists(f.temp_path()));
}

TEST(AtomicFile, CommitAsStoresTheFileUnderAnotherName) {
    const fs::path dir = fresh_dir();
    std::ofstream(dir / "run.csv") << "complete";
    AtomicFile f(dir / "run.csv");
    std::ofstream(f.temp_path()) << "partial";
    f.commit_as(dir / "run.interrupted.csv");
    std::ifstream kept(dir / "run.csv"), apart(dir / "run.interrupted.csv");
    std::string a, b;
    kept >> a;
    apart >> b;
    EXPECT_EQ(a, "complete");
    EXPECT_EQ(b, "partial");
}

} // namespace
} // namespace tumble::io
