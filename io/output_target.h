#pragma once
// What an output path names, decided once, before anything is written, so that an output is
// never renamed over something that is not a file (a device, a pipe, the node behind
// /dev/stdout). The rules, as a shell's `>` would have them, but crash-safe where it can be:
//   new path, or a regular file    replaced atomically (io/atomic_file.h); a symlink to a regular
//                                  file (or to a new path) is followed and its target replaced
//   "-", or the file standard      streamed to standard output as it is produced
//   output already is (/dev/stdout)
//   a FIFO (named pipe)            streamed into the pipe, in place
//   anything else (a directory, a  refused with OutputRefused (bad input, exit 2), naming the
//   character or block device,     path and what it is
//   a socket)
// A stream cannot be taken back: a failed or interrupted run leaves what it wrote in the pipe.
#include "io/bad_input.h"

#include <filesystem>
#include <string>

namespace tumble::io {

struct OutputRefused : BadInput {
    using BadInput::BadInput;
};

enum class OutputKind {
    kReplace, // write a temporary file beside `path`, rename it over `path` when complete
    kStream,  // write `path` in place (a FIFO, or /dev/stdout), appending, never removing it
};

struct OutputTarget {
    OutputKind kind = OutputKind::kReplace;
    std::filesystem::path path; // what to replace or stream into (symlinks resolved)
    bool standard_output = false;
};

// Throws OutputRefused for the kinds above that are refused, and for a path that cannot be
// examined (a symlink loop, no permission), with the system's reason. A path below a missing
// folder or a file counts as new: the directory checks name the folder.
OutputTarget resolve_output(const std::filesystem::path& named);

// "a character device", "a directory", ... for the file at `path` (lstat: symlinks not
// followed), or "" when nothing is there.
std::string describe_file_kind(const std::filesystem::path& path);

} // namespace tumble::io
