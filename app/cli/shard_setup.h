#pragma once
// What `tumble render` makes of --frames A:B and --from-checkpoints DIR (docs/cluster.md): the
// range of frames it draws, what its output records about it, and the state it starts from.
#include "app/cli/render_setup.h"
#include "app/cluster/frame_range.h"
#include "app/run/render_frames.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"

#include <optional>
#include <string>

namespace tumble::app {

// --frames, or the whole run (or the one frame of --frame). A shard goes to an MP4 (its range on
// key frames) or a PNG sequence (any range), or to null; anything else is refused. Sets
// cmd.output to "<scene>_<A>-<B>.mp4" when --frames is given without -o. Throws io::BadInput.
FrameRange render_range(RenderCommand& cmd, const Scene& scene, const Timeline& tl);

// The sink's share of the run: the shard's frames, and for an MP4 its tumble-shard tag.
RunOutput run_output(const RenderCommand& cmd, const Scene& scene, const Timeline& tl,
                     FrameRange range, const std::string& output);

// The checkpoint to continue from (--from-checkpoints), with a note on stderr saying which, or
// that there is none at or before the range's first frame. Throws CheckpointError.
std::optional<ResumePoint> resume_point(const RenderCommand& cmd, const Scene& scene,
                                        const Timeline& tl, const Simulation& sim,
                                        FrameRange range);

} // namespace tumble::app
