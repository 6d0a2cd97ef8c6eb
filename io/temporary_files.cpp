#include "io/temporary_files.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <unistd.h>

namespace tumble::io {

namespace fs = std::filesystem;

namespace {

// Process-wide because signals are: a fixed table of lock-free slots the handler can read.
constexpr std::size_t kSlots = 256;
std::array<std::atomic<const char*>, kSlots> g_slots{};
static_assert(std::atomic<const char*>::is_always_lock_free);

// ".<name>.<pid>.partial" -> name and pid; false for any other file name.
bool parse_temporary_name(const std::string& file, std::string& name, long& pid) {
    const std::string suffix = ".partial";
    if (file.size() < 1 + suffix.size() + 2 || file[0] != '.' || !file.ends_with(suffix))
        return false;
    const std::string middle = file.substr(1, file.size() - 1 - suffix.size()); // name.pid
    const std::size_t dot = middle.rfind('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == middle.size()) return false;
    const std::string digits = middle.substr(dot + 1);
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
        return false;
    name = middle.substr(0, dot);
    pid = std::stol(digits);
    return pid > 0;
}

bool process_is_gone(long pid) {
    return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

} // namespace

bool register_temporary(const char* path) noexcept {
    for (auto& slot : g_slots) {
        const char* empty = nullptr;
        if (slot.compare_exchange_strong(empty, path)) return true;
    }
    return false;
}

void unregister_temporary(const char* path) noexcept {
    for (auto& slot : g_slots) {
        const char* expected = path;
        if (slot.compare_exchange_strong(expected, nullptr)) return;
    }
}

int remove_registered_temporaries() noexcept {
    int removed = 0;
    for (auto& slot : g_slots) {
        const char* path = slot.exchange(nullptr);
        if (path && ::unlink(path) == 0) ++removed;
    }
    return removed;
}

std::vector<StaleTemporary>
remove_stale_temporaries(const fs::path& dir,
                         const std::function<bool(const std::string&)>& wanted) {
    std::vector<StaleTemporary> removed;
    std::error_code ec;
    fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        std::string name;
        long pid = 0;
        if (!parse_temporary_name(it->path().filename().string(), name, pid)) continue;
        if (pid == ::getpid() || !wanted(name) || !process_is_gone(pid)) continue;
        std::error_code gone;
        if (it->is_regular_file(gone) && fs::remove(it->path(), gone))
            removed.push_back({dir / it->path().filename(), pid});
    }
    return removed;
}

std::vector<StaleTemporary> remove_stale_temporaries(const fs::path& final_path) {
    const std::string mine = final_path.filename().string();
    return remove_stale_temporaries(final_path.parent_path(),
                                    [&mine](const std::string& name) { return name == mine; });
}

} // namespace tumble::io
