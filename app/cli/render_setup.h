#pragma once
// The options of `tumble render`: the scene's (scene_options.h), the picture's and the output's
// (app/run/render_request.h: what the Python module's keywords mean too), and those only the
// command line has (--stats, shards: --frames, --from-checkpoints).
#include "app/cli/scene_options.h"
#include "app/run/render_request.h"

#include <optional>
#include <string>

namespace tumble::app {

struct RenderCommand : RenderRequest {
    SceneOptions common;
    bool stats = false; // print each pipeline stage's rate
    // A shard: frames A..B-1 only ("A:B", app/cluster/frame_range.h), continuing from the
    // nearest checkpoint at or before A in `from_checkpoints` when given.
    std::optional<std::string> frames;
    std::string from_checkpoints;
};

} // namespace tumble::app
