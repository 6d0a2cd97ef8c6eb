#include "app/scene/input_file.h"

#include "app/scene/scene_error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/stat.h>

namespace tumble::app {

namespace {

std::string megabytes(std::uintmax_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1 << 20));
    return text;
}

struct CloseFile {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

} // namespace

std::string read_input_file(const std::filesystem::path& path, const std::string& what) {
    const std::string name = path.string();
    // Checked before opening (opening a FIFO would wait for a writer) and again on the opened
    // file (what is checked is what is read, even if the name changed hands in between).
    struct stat named {};
    if (::stat(name.c_str(), &named) == 0 && !S_ISREG(named.st_mode))
        throw SceneError(name, "file", "the " + what + " is not a regular file");
    std::unique_ptr<std::FILE, CloseFile> file(std::fopen(name.c_str(), "rb"));
    if (!file)
        throw SceneError(name, "file", "cannot open the " + what + ": " + std::strerror(errno));
    struct stat st {};
    if (::fstat(fileno(file.get()), &st) != 0 || !S_ISREG(st.st_mode))
        throw SceneError(name, "file", "the " + what + " is not a regular file");
    const auto size = static_cast<std::uintmax_t>(st.st_size);
    if (size > kMaxInputFileBytes)
        throw SceneError(name, "file",
                         "the " + what + " is " + megabytes(size) + "; Tumble reads at most " +
                             megabytes(kMaxInputFileBytes) + " from one file");
    std::string text(size, '\0');
    const std::size_t got = std::fread(text.data(), 1, size, file.get());
    if (got != size || std::ferror(file.get()))
        throw SceneError(name, "file",
                         "cannot read the " + what + " (" + std::to_string(got) + " of " +
                             std::to_string(size) + " bytes)");
    return text;
}

} // namespace tumble::app
