#pragma once
// Frame ranges of a shard: `tumble render --frames A:B` draws frames A to B - 1 of the whole run
// (half-open, so 0:60 and 60:120 tile the first two seconds at 60 fps), and `tumble shards`
// splits a run into such ranges. A video shard must start on a key frame of the whole run, one
// every key_interval() frames (app/run/key_interval.h), so that its packets are those of a whole
// render (the encoder restarts there: render/video_sink.h); its end is the next shard's start, or
// the end of the run.
#include "app/run/key_interval.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tumble::app {

struct FrameRange {
    std::int64_t first = 0; // the first frame drawn
    std::int64_t end = 0;   // one past the last
    std::int64_t size() const { return end - first; }
    std::string text() const { return std::to_string(first) + ":" + std::to_string(end); }
};

// Parses "A:B" as given to `option`. Throws io::BadInput naming option, text and what was
// expected unless 0 <= A < B <= frames and A and B are multiples of `key_interval` (B may also be
// `frames`, the end of the run). key_interval 1 allows any range (PNG frames).
FrameRange parse_frame_range(const std::string& option, const std::string& text,
                             std::int64_t frames, int key_interval);

// [0, frames) as `count` consecutive ranges starting on key frames, as even as whole key-frame
// segments allow (the first ones take one segment more when they do not divide evenly). Throws
// io::BadInput naming --count when there are fewer segments than `count`, or count < 1.
std::vector<FrameRange> split_frames(std::int64_t frames, int key_interval, int count);

} // namespace tumble::app
