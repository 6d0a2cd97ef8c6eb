#pragma once
// Runs the real `tumble` binary the way a user would, in a fresh scratch directory, and captures
// its exit code and output.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace tumble::test {

struct CliResult {
    int exit_code = -1;
    std::string out, err;
};

// A scratch directory under the build tree, emptied at construction, named after the test.
inline std::filesystem::path scratch_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path dir = std::filesystem::path(TUMBLE_TEST_ARTIFACTS) / "cli" /
                                (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

// Runs the shell command `line` (which names tumble as "$TUMBLE") with the working directory
// `dir`.
inline CliResult run_shell(const std::filesystem::path& dir, const std::string& line) {
    const std::string cmd = "cd '" + dir.string() + "' && TUMBLE='" + std::string(TUMBLE_EXE) +
                            "' && (" + line + ") > stdout.txt 2> stderr.txt";
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = read_text(dir / "stdout.txt");
    r.err = read_text(dir / "stderr.txt");
    std::filesystem::remove(dir / "stdout.txt");
    std::filesystem::remove(dir / "stderr.txt");
    return r;
}

// Runs `tumble <args>` with the working directory `dir`.
inline CliResult run_tumble(const std::filesystem::path& dir, const std::string& args) {
    return run_shell(dir, "\"$TUMBLE\" " + args);
}

// Every file in `dir` (recursively), as paths relative to it.
inline std::vector<std::string> files_in(const std::filesystem::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.is_regular_file()) out.push_back(std::filesystem::relative(e.path(), dir).string());
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace tumble::test
