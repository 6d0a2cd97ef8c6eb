#pragma once
// The temporary files of unfinished outputs (io/atomic_file.h), tracked so that nothing half
// written outlives the run that wrote it:
//  * while a process runs, each temporary file it has open is registered here, so a second
//    Ctrl-C, which exits at once, can still delete them: remove_registered_temporaries() only
//    calls unlink(2), which is async-signal-safe, on paths held in lock-free slots;
//  * a process killed outright (SIGKILL, a crash, a power cut) cannot clean up, so the next run
//    writing the same output removes temporaries whose process is gone (remove_stale_...).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace tumble::io {

// Registers a temporary file's path; `path` must stay valid until unregister_temporary(path).
// Returns false (and cleanup on a second signal will miss this file) when all slots are taken.
bool register_temporary(const char* path) noexcept;
void unregister_temporary(const char* path) noexcept;
// Deletes every registered temporary file. Async-signal-safe; returns how many it removed.
int remove_registered_temporaries() noexcept;

struct StaleTemporary {
    std::filesystem::path path;
    long pid = 0; // the process that wrote it, no longer running
};

// In `dir`, deletes temporary files ".<name>.<pid>.partial" whose final <name> satisfies
// `wanted` and whose process no longer exists on this machine (kill(pid, 0) gives ESRCH);
// returns what it deleted. Temporaries of running processes, this one included, are kept.
std::vector<StaleTemporary>
remove_stale_temporaries(const std::filesystem::path& dir,
                         const std::function<bool(const std::string& name)>& wanted);
// The same for the one output `final_path`.
std::vector<StaleTemporary> remove_stale_temporaries(const std::filesystem::path& final_path);

} // namespace tumble::io
