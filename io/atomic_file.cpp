#include "io/atomic_file.h"

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
        const fs::path parent = dir.parent_path();
        if (!parent.empty() && !fs::is_directory(parent, ec)) {
            throw FileError("cannot create directory '" + dir.string() + "': its parent '" +
                            parent.string() + "' does not exist or is not a directory");
        }
        created = fs::create_directory(dir, ec);
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
    : final_(std::move(final_path)), temp_(temporary_path_for(final_)) {}

void AtomicFile::commit() {
    if (done_) throw FileError("'" + final_.string() + "' was already committed or discarded");
    std::error_code ec;
    fs::rename(temp_, final_, ec);
    if (ec) {
        discard();
        throw FileError("cannot rename '" + temp_.string() + "' to '" + final_.string() +
                        "': " + ec.message());
    }
    committed_ = true;
    done_ = true;
}

void AtomicFile::discard() noexcept {
    if (done_) return;
    std::error_code ec;
    fs::remove(temp_, ec); // a file that was never created is fine
    done_ = true;
}

} // namespace tumble::io
