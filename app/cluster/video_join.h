#pragma once
// `tumble join`: video shards of one run (`tumble render --frames A:B`) concatenated into one MP4
// without re-encoding. The packets are copied as they are (a libavformat remux) with their
// timestamps moved to the shard's place in the whole run, so the result holds exactly the
// packets of a single render of the same run: each shard starts on a key frame where the single
// render's encoder also started afresh (render/video_sink.h), hence decodes to the same frames.
//
// Shards are checked before anything is written, from their tumble-shard tags (shard_tag.h) and
// their streams: all from the same scene, build and settings, with the same stream headers,
// holding as many frames as their range says (an interrupted render is not a whole shard), and
// ranges that follow each other without gap or overlap once sorted (the shards may be given in
// any order, e.g. part_*.mp4 from a glob). Anything else is bad input naming the file and what is
// wrong; the output is then never created.
#include "app/cluster/shard_tag.h"

#include <string>
#include <vector>

namespace tumble::app {

struct JoinResult {
    ShardTag tag;                   // the joined video's (its range spans the shards')
    std::int64_t frames = 0;        // packets written
    std::vector<std::string> order; // the shards in the order joined
};

// Writes `output` (temporary name, then rename; a FIFO gets fragmented MP4) from `parts`. Throws
// io::BadInput for shards that do not belong together or cannot be read, std::runtime_error when
// writing fails.
JoinResult join_videos(const std::vector<std::string>& parts, const std::string& output);

} // namespace tumble::app
