// Replays fuzz inputs without libFuzzer: the normal build links each harness with this main
// (the Fuzz.*Replay tests). It runs LLVMFuzzerTestOneInput once on every regular file of the
// folders given (not their subfolders; names starting with '.' skipped, e.g. .gitkeep), in sorted
// order, and prints how many it ran. Fails (exit 1) on an exception escaping the harness, naming
// the file; on a folder that does not exist; and when it ran no file at all, since a replay that
// checked nothing proves nothing. A crash names its file too (the signal handler below).
// Seeds are also held to their names (the harness says what its reader made of each input,
// harness_support.h): a file named good_* or asset_* must load and one named bad_* must be
// refused, so that a reader refusing every input, or accepting every one, fails the replay;
// any other name (libFuzzer's crash-<sha1>, merged coverage) may go either way.
//   fuzz_replay_<harness> <folder>...
#include "harness_support.h"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

char g_current[4096]; // the file being replayed, for the crash message

void on_crash(int sig) {
    constexpr char prefix[] = "replay: crashed on ";
    [[maybe_unused]] ssize_t n = write(STDERR_FILENO, prefix, sizeof prefix - 1);
    n = write(STDERR_FILENO, g_current, std::strlen(g_current));
    n = write(STDERR_FILENO, "\n", 1);
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

// Names the file on a crash, for the signals nobody handles yet (a sanitizer may have its own).
void name_file_on_crash() {
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
        struct sigaction old {};
        if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_DFL)
            std::signal(sig, on_crash);
    }
}

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The regular files directly in `folder`, sorted; false when it is not a folder.
bool inputs_in(const fs::path& folder, std::vector<fs::path>& out) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return false;
    std::vector<fs::path> found;
    for (const fs::directory_entry& e : fs::directory_iterator(folder))
        if (e.is_regular_file() && e.path().filename().string().rfind('.', 0) != 0)
            found.push_back(e.path());
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
    return true;
}

// What a seed's name promises: good_* and asset_* load, bad_* are refused, others either.
tumble::fuzz::Verdict promised(const fs::path& file) {
    const std::string name = file.filename().string();
    const auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
    if (starts("good_") || starts("asset_")) return tumble::fuzz::Verdict::kLoaded;
    if (starts("bad_")) return tumble::fuzz::Verdict::kRefused;
    return tumble::fuzz::Verdict::kNone;
}

const char* describe(tumble::fuzz::Verdict v) {
    switch (v) {
    case tumble::fuzz::Verdict::kLoaded:
        return "loaded";
    case tumble::fuzz::Verdict::kRefused:
        return "refused";
    case tumble::fuzz::Verdict::kNone:
        break;
    }
    return "neither loaded nor refused";
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s <folder>...\n", argv[0]);
        return 2;
    }
    std::vector<fs::path> files;
    for (int k = 1; k < argc; ++k)
        if (!inputs_in(argv[k], files)) {
            std::fprintf(stderr, "replay: no folder %s\n", argv[k]);
            return 1;
        }
    name_file_on_crash();
    int held = 0, broken = 0; // seeds held to their names; of those, how many broke the promise
    for (const fs::path& file : files) {
        std::snprintf(g_current, sizeof g_current, "%s", file.c_str());
        const std::vector<std::uint8_t> bytes = read_bytes(file);
        const std::uint8_t none = 0; // libFuzzer never passes a null pointer, even for 0 bytes
        tumble::fuzz::last_verdict() = tumble::fuzz::Verdict::kNone;
        try {
            LLVMFuzzerTestOneInput(bytes.empty() ? &none : bytes.data(), bytes.size());
        } catch (const std::exception& e) {
            std::fprintf(stderr, "replay: %s: exception escaped the harness: %s\n", g_current,
                         e.what());
            return 1;
        } catch (...) {
            std::fprintf(stderr, "replay: %s: a non-standard exception escaped\n", g_current);
            return 1;
        }
        const tumble::fuzz::Verdict expected = promised(file);
        if (expected == tumble::fuzz::Verdict::kNone) continue;
        ++held;
        if (tumble::fuzz::last_verdict() != expected) {
            ++broken;
            std::fprintf(stderr, "replay: %s: expected to be %s by its name, but was %s\n",
                         g_current, describe(expected), describe(tumble::fuzz::last_verdict()));
        }
    }
    std::printf("replayed %zu files from %d folders; %d seeds held to their names (good_*, "
                "asset_* load; bad_* refused), %d broke it\n",
                files.size(), argc - 1, held, broken);
    if (files.empty()) std::fprintf(stderr, "replay: no input files: nothing was checked\n");
    return files.empty() || broken > 0 ? 1 : 0;
}
