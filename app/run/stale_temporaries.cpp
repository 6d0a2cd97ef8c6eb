#include "app/run/stale_temporaries.h"

#include "io/temporary_files.h"
#include "render/png_sink.h"

#include <cstdio>
#include <vector>

namespace tumble::app {

namespace fs = std::filesystem;

namespace {

// The frame files of a sequence output, or nothing for a single file.
std::optional<render::FramePattern> frames_of(const std::string& output) {
    try {
        return render::FramePattern::of_output(output);
    } catch (const std::exception&) {
        return std::nullopt; // a bad pattern: the sink will refuse it with the full message
    }
}

std::vector<io::StaleTemporary> remove_for(const std::string& output) {
    const std::optional<render::FramePattern> frames = frames_of(output);
    if (!frames) return io::remove_stale_temporaries(fs::path(output));
    const fs::path first = frames->name(0);
    const std::string head = fs::path(frames->prefix).filename().string(); // "" for "dir/"
    const std::string tail = frames->suffix;
    return io::remove_stale_temporaries(first.parent_path(), [&](const std::string& name) {
        return name.size() >= head.size() + tail.size() && name.starts_with(head) &&
               name.ends_with(tail);
    });
}

} // namespace

void remove_stale_temporaries_for(const std::string& output, bool quiet) {
    if (output.empty() || output == "-") return;
    for (const io::StaleTemporary& stale : remove_for(output)) {
        if (quiet) continue;
        std::fprintf(stderr, "tumble: note: removed '%s', left by process %ld, no longer running\n",
                     stale.path.c_str(), stale.pid);
    }
}

} // namespace tumble::app
