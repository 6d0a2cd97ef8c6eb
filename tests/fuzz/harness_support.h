#pragma once
// Shared by the fuzz harnesses (tests/fuzz/*_fuzz.cpp): a promise check that turns a broken
// promise into a crash libFuzzer records, what the reader made of the last input (for the
// replay's check that the valid seeds load), and a per-process scratch folder for the readers
// that take a file rather than text.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace tumble::fuzz {

// Aborts with `what` (and the start of `detail`, e.g. the error message judged) unless `ok`:
// libFuzzer keeps the input as a crash, the replay fails.
inline void require(bool ok, const char* what, const std::string& detail = "") {
    if (ok) return;
    std::fprintf(stderr, "fuzz: broken promise: %s\n", what);
    if (!detail.empty())
        std::fprintf(stderr, "fuzz: %zu bytes: %.300s\n", detail.size(), detail.c_str());
    std::abort();
}

// What the harness's reader made of the last input, set by each harness: loaded (a scene or a
// suite came out) or refused (io::BadInput). libFuzzer ignores it; the replay (replay_main.cpp)
// holds the corpus's seeds to their names: good_* and asset_* must load, bad_* must be refused,
// so that a reader refusing everything (or accepting everything) fails the replay.
enum class Verdict { kNone, kLoaded, kRefused };

inline Verdict& last_verdict() {
    static Verdict verdict = Verdict::kNone;
    return verdict;
}

// A refusal's message names the input first (the file, or the scene's source) and is short: a
// line or two, since no message quotes a whole value (the limit leaves room for long paths).
inline void require_clear_error(const std::string& what, const std::string& source) {
    require(what.rfind(source, 0) == 0, "the error message starts with the input's name", what);
    require(what.size() <= 4096, "the error message is short", what);
}

// <temp>/tumble-fuzz-<pid>/: made on first use, removed at a normal exit. One per process, so
// parallel fuzzing jobs (-jobs, -fork) never share a file. The path is never freed, so it is still
// there when the exit handler removes the folder (a static path would be destroyed before it).
inline const std::filesystem::path& scratch_dir() {
    static const std::filesystem::path* dir = [] {
        auto* d = new std::filesystem::path(std::filesystem::temp_directory_path() /
                                            ("tumble-fuzz-" + std::to_string(long(getpid()))));
        std::filesystem::create_directories(*d);
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(*dir, ec);
        });
        return d;
    }();
    return *dir;
}

// Writes the input bytes to `name` in the scratch folder and returns its path. A new file each
// time: ext4 flushes a file truncated and rewritten when it is closed (auto_da_alloc), which
// made every run take milliseconds.
inline std::filesystem::path write_scratch(const char* name, const std::uint8_t* data,
                                           std::size_t size) {
    const std::filesystem::path path = scratch_dir() / name;
    std::error_code ec;
    std::filesystem::remove(path, ec);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    require(out.good(), "the scratch file was written (disk full?)");
    return path;
}

} // namespace tumble::fuzz
