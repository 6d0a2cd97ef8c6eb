// io/temporary_files.h: the registry a second Ctrl-C empties, and the removal of temporaries of
// processes that no longer run (and only those).
#include "io/atomic_file.h"
#include "io/io_scratch.h"
#include "io/temporary_files.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

// The pid of a process that has exited and been reaped: nothing runs under it (until the
// system hands the number out again, which takes tens of thousands of new processes).
long dead_pid() {
    const pid_t pid = fork();
    if (pid == 0) _exit(0);
    waitpid(pid, nullptr, 0);
    return pid;
}

void touch(const fs::path& p) {
    std::ofstream(p) << "partial";
}

TEST(TemporaryFiles, RemovingTheRegisteredOnesDeletesEveryOpenTemporary) {
    const fs::path dir = fresh_dir();
    AtomicFile a(dir / "a.mp4"), b(dir / "b.csv");
    touch(a.temp_path());
    touch(b.temp_path());
    EXPECT_EQ(remove_registered_temporaries(), 2);
    EXPECT_FALSE(fs::exists(a.temp_path()));
    EXPECT_FALSE(fs::exists(b.temp_path()));
    EXPECT_EQ(remove_registered_temporaries(), 0); // emptied
}

TEST(TemporaryFiles, ACommittedFileIsNoLongerRegistered) {
    const fs::path dir = fresh_dir();
    AtomicFile a(dir / "a.csv");
    touch(a.temp_path());
    a.commit();
    EXPECT_EQ(remove_registered_temporaries(), 0);
    EXPECT_TRUE(fs::exists(dir / "a.csv"));
}

TEST(TemporaryFiles, OnlyTemporariesOfDeadProcessesForThisOutputAreRemoved) {
    const fs::path dir = fresh_dir();
    const long dead = dead_pid();
    const std::string d = std::to_string(dead);
    touch(dir / (".out.mp4." + d + ".partial"));                         // removed
    touch(dir / (".out.mp4." + std::to_string(getpid()) + ".partial"));  // this process
    touch(dir / (".out.mp4." + std::to_string(getppid()) + ".partial")); // a live process
    touch(dir / (".other.mp4." + d + ".partial"));                       // another output
    touch(dir / ("out.mp4." + d + ".partial"));                          // not our naming
    const std::vector<StaleTemporary> removed = remove_stale_temporaries(dir / "out.mp4");
    ASSERT_EQ(removed.size(), 1u);
    EXPECT_EQ(removed[0].path, dir / (".out.mp4." + d + ".partial"));
    EXPECT_EQ(removed[0].pid, dead);
    int left = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++left;
    EXPECT_EQ(left, 4);
}

} // namespace
} // namespace tumble::io
