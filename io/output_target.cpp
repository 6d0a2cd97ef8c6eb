#include "io/output_target.h"

#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace tumble::io {

namespace fs = std::filesystem;

namespace {

const char* kind_of(mode_t mode) {
    if (S_ISREG(mode)) return "a regular file";
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISLNK(mode)) return "a symbolic link";
    return "not a file";
}

// True when `st` is the very file descriptor 1 is open on (a terminal, a pipe or a file).
bool is_standard_output(const struct stat& st) {
    struct stat out {};
    return ::fstat(STDOUT_FILENO, &out) == 0 && out.st_dev == st.st_dev && out.st_ino == st.st_ino;
}

OutputTarget standard_output() {
    return {OutputKind::kStream, "/dev/stdout", true};
}

// A new path, possibly through a symlink that points nowhere yet: follow it, as `>` would.
OutputTarget new_path(const fs::path& named) {
    std::error_code ec;
    if (!fs::is_symlink(named, ec)) return {OutputKind::kReplace, named, false};
    fs::path target = fs::read_symlink(named, ec);
    if (ec) return {OutputKind::kReplace, named, false};
    if (target.is_relative()) target = named.parent_path() / target;
    return {OutputKind::kReplace, fs::weakly_canonical(target, ec), false};
}

} // namespace

std::string describe_file_kind(const fs::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return "";
    return kind_of(st.st_mode);
}

OutputTarget resolve_output(const fs::path& named) {
    if (named == "-") return standard_output();
    struct stat st {};
    if (::stat(named.c_str(), &st) != 0) { // stat follows symlinks
        const int error = errno;
        // Nothing there yet; a missing or non-directory folder above is for the directory checks
        // (ensure_writable_directory), which name the folder.
        if (error == ENOENT || error == ENOTDIR) return new_path(named);
        throw OutputRefused("cannot write to '" + named.string() + "': " + std::strerror(error));
    }
    if (is_standard_output(st)) return standard_output();
    if (S_ISREG(st.st_mode)) {
        std::error_code ec;
        const fs::path target = fs::is_symlink(named, ec) ? fs::canonical(named, ec) : named;
        return {OutputKind::kReplace, ec ? named : target, false};
    }
    if (S_ISFIFO(st.st_mode)) return {OutputKind::kStream, named, false};
    throw OutputRefused("cannot write to '" + named.string() + "': it is " + kind_of(st.st_mode) +
                        "; an output must be a new path, a regular file, a FIFO, or standard "
                        "output ('-'), and Tumble never replaces anything else");
}

} // namespace tumble::io
