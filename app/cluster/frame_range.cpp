#include "app/cluster/frame_range.h"

#include "io/bad_input.h"

#include <algorithm>

#include <charconv>

namespace tumble::app {

namespace {

// "--frames 30:90: what was expected" (a SceneError would read "--frames:30:90:" as line:column).
io::BadInput refused(const std::string& option, const std::string& text, const std::string& what) {
    return io::BadInput(option + " " + text + ": " + what);
}

bool parse_index(std::string_view text, std::int64_t& out) {
    const char* end = text.data() + text.size();
    const auto [at, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && at == end && !text.empty();
}

} // namespace

FrameRange parse_frame_range(const std::string& option, const std::string& text,
                             std::int64_t frames, int key_interval) {
    const std::string whole = "0:" + std::to_string(frames);
    const auto colon = text.find(':');
    FrameRange r;
    if (colon == std::string::npos ||
        !parse_index(std::string_view(text).substr(0, colon), r.first) ||
        !parse_index(std::string_view(text).substr(colon + 1), r.end))
        throw refused(option, text,
                      "expected FIRST:END, frames FIRST to END - 1 (e.g. " + whole +
                          " for the whole run)");
    if (r.first < 0 || r.first >= r.end || r.end > frames)
        throw refused(option, text,
                      "expected 0 <= FIRST < END <= " + std::to_string(frames) + " (the run has " +
                          std::to_string(frames) + " frames: " + whole + ")");
    const auto on_key = [&](std::int64_t k) { return k % key_interval == 0; };
    if (!on_key(r.first) || (!on_key(r.end) && r.end != frames))
        throw refused(option, text,
                      "a video shard starts and ends on key frames: expected multiples of " +
                          std::to_string(key_interval) +
                          " (a key frame every two seconds), or END = " + std::to_string(frames) +
                          " (`tumble shards` prints such ranges)");
    return r;
}

std::vector<FrameRange> split_frames(std::int64_t frames, int key_interval, int count) {
    const std::int64_t segments = (frames + key_interval - 1) / key_interval;
    if (count < 1 || count > segments)
        throw refused("--count", std::to_string(count),
                      "expected 1 to " + std::to_string(segments) + " shards: the run has " +
                          std::to_string(frames) + " frames, " + std::to_string(segments) +
                          " key-frame segment" + (segments == 1 ? "" : "s") + " of " +
                          std::to_string(key_interval) + " frames");
    std::vector<FrameRange> out;
    std::int64_t segment = 0;
    for (int i = 0; i < count; ++i) {
        const std::int64_t take = segments / count + (i < segments % count ? 1 : 0);
        FrameRange r{segment * key_interval, std::min(frames, (segment + take) * key_interval)};
        out.push_back(r);
        segment += take;
    }
    return out;
}

} // namespace tumble::app
