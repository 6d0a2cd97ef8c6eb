#include "io/atomic_file.h"

#include "io/temporary_files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace tumble::io {

namespace fs = std::filesystem;

fs::path temporary_path_for(const fs::path& final_path) {
    // Appended piece by piece: GCC 12 gives a false -Wrestrict for "." + string + ... (PR 105651).
    std::string name = ".";
    name += final_path.filename().string();
    name += '.';
    name += std::to_string(::getpid());
    name += ".partial";
    return final_path.parent_path() / name;
}

namespace {

std::string shown(const fs::path& dir) {
    return dir.empty() ? std::string(".") : dir.string();
}

// Creating a file is the only reliable writability test: access(2) says yes to root even on a
// read-only file system, and permission bits say nothing about ACLs or full disks.
void probe_writable(const fs::path& dir) {
    const fs::path probe = (dir.empty() ? fs::path(".") : dir) / temporary_path_for("write-test");
    std::FILE* file = std::fopen(probe.c_str(), "wb");
    if (!file) {
        const int error = errno;
        throw FileError("cannot write in directory '" + shown(dir) + "': " + std::strerror(error));
    }
    std::fclose(file);
    std::remove(probe.c_str());
}

} // namespace

bool ensure_writable_directory(const fs::path& dir) {
    std::error_code ec;
    bool created = false;
    if (!dir.empty() && !fs::exists(dir, ec)) {
        created = fs::create_directories(dir, ec);
        if (ec) {
            throw FileError("cannot create directory '" + dir.string() + "': " + ec.message());
        }
    }
    if (!dir.empty() && !fs::is_directory(dir, ec)) {
        throw FileError("'" + dir.string() + "' is not a directory");
    }
    probe_writable(dir);
    return created;
}

AtomicFile::AtomicFile(fs::path final_path)
    : final_(std::move(final_path)), target_(resolve_output(final_)),
      temp_(streaming() ? target_.path : temporary_path_for(target_.path)) {
    if (!streaming()) register_temporary(temp_.c_str());
}

void AtomicFile::commit() {
    commit_as(target_.path);
}

void AtomicFile::commit_as(const fs::path& other) {
    if (done_) throw FileError("'" + final_.string() + "' was already committed or discarded");
    if (streaming()) {
        committed_ = done_ = true;
        return;
    }
    // The destination was checked when this file was opened; a run takes a while, so check
    // again: rename(2) would replace a device node or a FIFO as readily as a file.
    const std::string kind = describe_file_kind(other);
    if (!kind.empty() && kind != "a regular file" && kind != "a symbolic link") {
        discard();
        throw FileError("cannot write '" + other.string() + "': it is now " + kind +
                        ", which Tumble never replaces");
    }
    std::error_code ec;
    fs::rename(temp_, other, ec);
    if (ec) {
        discard();
        throw FileError("cannot rename '" + temp_.string() + "' to '" + other.string() +
                        "': " + ec.message());
    }
    unregister_temporary(temp_.c_str());
    committed_ = done_ = true;
}

void AtomicFile::discard() noexcept {
    if (done_) return;
    done_ = true;
    if (streaming()) return; // a pipe keeps what it was given; it is never removed
    std::error_code ec;
    fs::remove(temp_, ec); // a file that was never created is fine
    unregister_temporary(temp_.c_str());
}

} // namespace tumble::io
