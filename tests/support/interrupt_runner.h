#pragma once
// Runs `tumble` in the background to interrupt it the way a user would (Ctrl-C, kill), on a sign
// of progress rather than after a wall-clock guess, and waits for it with a deadline so a signal
// handler that fails cannot hang the suite: past the deadline the run is killed and the test
// fails.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace tumble::test {

// A started run that must not outlive its test: killed (SIGKILL) and reaped when the test leaves
// the scope before the run ended, e.g. on a failed ASSERT.
struct ChildGuard {
    pid_t pid;
    ~ChildGuard() {
        int status = 0;
        if (pid > 0 && waitpid(pid, &status, WNOHANG) == 0) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
        }
    }
};

// Starts `tumble <args>` in `dir`, its standard error going to dir/stderr.txt.
inline pid_t start_tumble(const std::filesystem::path& dir, const std::string& args) {
    const pid_t pid = fork();
    if (pid == 0) {
        if (chdir(dir.c_str()) != 0) _exit(99);
        if (!freopen("stderr.txt", "w", stderr)) _exit(97);
        execl("/bin/sh", "sh", "-c", ("exec " + std::string(TUMBLE_EXE) + " " + args).c_str(),
              static_cast<char*>(nullptr));
        _exit(98);
    }
    return pid;
}

// Waits (60 s at most) until process `pid` is Tumble (start_tumble's shell has exec'd it: the
// Name in /proc/PID/status) and handles `signal` itself (its SigCgt mask has the bit): from then
// on a signal reaches Tumble's handler, not the default action. The name matters: dash, the shell
// that starts it, catches SIGINT too, and a slow start (a sanitizer build on a busy machine took
// longer than the callers' 500 ms) would otherwise let the signal kill Tumble before its handler
// is in place. Returns false if that never happened.
inline bool wait_until_handling(pid_t pid, int signal) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    const std::string status = "/proc/" + std::to_string(pid) + "/status";
    const std::string name =
        "Name:\t" + std::filesystem::path(TUMBLE_EXE).filename().string().substr(0, 15) + "\n";
    for (;;) {
        const std::string text = read_text(status);
        const auto at = text.find("SigCgt:");
        if (text.find(name) != std::string::npos && at != std::string::npos &&
            (std::stoull(text.substr(at + 7, 24), nullptr, 16) >> (signal - 1) & 1))
            return true;
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

// Waits (240 s at most: a busy machine is slow to start) until a file in `dir` whose name starts
// with `prefix` holds more than a
// header (an MP4's first 48 bytes are flushed when it is opened, a CSV's header row sits in
// stdio's buffer): the run is writing results. Returns false if that never happened.
// Waits (60 s at most) until `file` holds `text`. Returns false if that never happened.
inline bool wait_until_said(const std::filesystem::path& file, const std::string& text) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (read_text(file).find(text) == std::string::npos) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

inline bool wait_until_writing(const std::filesystem::path& dir, const std::string& prefix) {
    constexpr std::uintmax_t kMoreThanAHeader = 1024;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(240);
    auto writing = [&] {
        std::error_code ec;
        for (const auto& e : std::filesystem::directory_iterator(dir, ec))
            if (e.path().filename().string().starts_with(prefix) &&
                e.file_size(ec) > kMoreThanAHeader)
                return true;
        return false;
    };
    while (!writing()) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return true;
}

// The exit code of `pid` (128 + signal if a signal ended it), or -1 when it had not ended within
// `limit`: it is then killed, and the caller's expectation on the code fails.
inline int wait_for_exit(pid_t pid, std::chrono::seconds limit = std::chrono::seconds(120)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            ADD_FAILURE() << "tumble did not exit within " << limit.count() << " s of the signal";
            return -1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Starts `tumble <args>` in `dir`, sends `signal` once a file starting with `partial_prefix` has
// results in it, and returns the exit code.
inline int interrupt_when_writing(const std::filesystem::path& dir, const std::string& args,
                                  const std::string& partial_prefix, int signal) {
    const pid_t pid = start_tumble(dir, args);
    const ChildGuard child{pid};
    EXPECT_TRUE(wait_until_writing(dir, partial_prefix)) << "never started writing";
    kill(pid, signal);
    return wait_for_exit(pid);
}

} // namespace tumble::test
