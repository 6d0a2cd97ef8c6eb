#pragma once
// Crash-safe file output. A file is written under a temporary name in the same directory as its
// final name and renamed over it only once complete: rename(2) within one file system is atomic,
// so a reader (or a user after Ctrl-C or a crash) sees either the old file, the complete new one,
// or nothing, never a half-written file. Temporary names start with '.' so they stay out of
// directory listings and globs like frames/*.png, and carry the process id so two processes
// writing the same output do not trample each other's temporary file (and a later run can tell
// a dead process's leftovers: io/temporary_files.h).
//
// What the final name is decides how it is written (io/output_target.h): a new path or a regular
// file is replaced as above; a FIFO or standard output is streamed into in place and never
// removed; anything else (a device, a directory) is refused before anything is written.
#include "io/output_target.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace tumble::io {

struct FileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "dir/name.ext" -> "dir/.name.ext.<pid>.partial"
std::filesystem::path temporary_path_for(const std::filesystem::path& final_path);

// Makes sure `dir` is a directory this process can create files in, creating it and any missing
// parents (one rule for every command's output: issue 14). Throws FileError naming the directory
// otherwise. An empty path means the current directory. Returns true when it created `dir`.
bool ensure_writable_directory(const std::filesystem::path& dir);

// Owns one temporary file until commit() renames it to the final name. If neither commit() nor
// discard() ran, the destructor deletes the temporary file, so an exception between creating and
// finishing a file cleans up after itself. While it exists, a second Ctrl-C deletes it too.
class AtomicFile {
  public:
    // Throws OutputRefused (bad input) when `final_path` is something Tumble must not replace.
    explicit AtomicFile(std::filesystem::path final_path);
    ~AtomicFile() { discard(); }
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Where to write the contents (the caller opens, writes and closes it): the temporary file,
    // or for a stream the FIFO or /dev/stdout itself.
    const std::filesystem::path& temp_path() const { return temp_; }
    // The output as the user named it (for messages).
    const std::filesystem::path& final_path() const { return final_; }
    bool streaming() const { return target_.kind == OutputKind::kStream; }
    bool standard_output() const { return target_.standard_output; }
    // fopen(temp_path(), mode): a stream is appended to (never truncated: `>> log` stays whole).
    const char* fopen_mode() const { return streaming() ? "ab" : "wb"; }

    // Renames the temporary file to the final name, replacing any regular file already there
    // (checked again now: never a device or pipe that appeared meanwhile). Throws FileError (and
    // deletes the temporary file) when it cannot. Nothing to do for a stream.
    void commit();
    // The same, but into `other` instead of the final name (e.g. a name saying "interrupted").
    void commit_as(const std::filesystem::path& other);
    // Deletes the temporary file if it still exists (never a stream). Never throws.
    void discard() noexcept;
    bool committed() const { return committed_; }

  private:
    std::filesystem::path final_;
    OutputTarget target_;
    std::filesystem::path temp_;
    bool committed_ = false;
    bool done_ = false; // committed or discarded: nothing left to clean up
};

} // namespace tumble::io
