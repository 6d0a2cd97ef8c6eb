#pragma once
// What a video made by `tumble render` says about itself, so that `tumble join` can tell whether
// shards belong together: the MP4's "comment" tag, one line of key=value words,
//   tumble-shard/1 frames=60:120/600 scene=<hash> look=<hash> build=<id> size=1280x720 fps=60
//   codec=libx264 crf=18 preset=medium keyint=60
// frames: the range A:B of the whole run's frames it holds, and the run's frame count; scene: the
// scene inputs' content hash (Scene::content_hash); look: a hash of what the command line can
// change about the pictures and the motion (integrator, step, size, frame rate, the picture
// switches such as --no-shadows); build: build_id(); the rest: the encoder's settings. A whole
// render is the one shard 0:N/N, so it can be joined too.
#include "app/cluster/frame_range.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tumble::app {

struct ShardTag {
    FrameRange range;
    std::int64_t frames = 0; // of the whole run
    std::string scene, look, build;
    int width = 0, height = 0, fps = 0;
    std::string codec; // libx264
    int crf = 0;
    std::string preset;
    int key_interval = 0;
};

// The tag of a render of `range` of the run `tl` of `scene` (after the command line's overrides)
// encoded with libx264 at `crf` and `preset`.
ShardTag shard_tag_for(const Scene& scene, const Timeline& tl, FrameRange range, int crf,
                       const std::string& preset);

std::string format_tag(const ShardTag& tag);

// Reads a comment tag: nothing when it is not a tumble-shard tag at all (another program's
// video); throws io::BadInput naming `file` when it is one but malformed or of another version.
std::optional<ShardTag> parse_tag(const std::string& comment, const std::string& file);

// The first setting in which two shards differ, as "scene 1a2b... against 3c4d..." (every field
// but the range), or "" when they are parts of the same run.
std::string tag_mismatch(const ShardTag& a, const ShardTag& b);

} // namespace tumble::app
