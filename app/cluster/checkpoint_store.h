#pragma once
// The checkpoints of a run in a folder, one file per frame: DIR/frame_000120.tck is the state
// shown by frame 120 (checkpoint.h has the format). `tumble simulate --checkpoint-every K` writes
// them; `tumble render --frames A:B --from-checkpoints DIR` continues from the one nearest at or
// before A.
#include "app/cluster/checkpoint.h"
#include "app/run/render_frames.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace tumble::app {

std::filesystem::path checkpoint_path(const std::filesystem::path& dir, std::int64_t frame);

// The header a checkpoint of this run at `frame` carries (and one it reads must match).
CheckpointHeader run_header(const Scene& scene, const Timeline& tl, const Simulation& sim,
                            std::int64_t frame);

// Writes sim's state as frame `frame`'s checkpoint into `dir` (created if missing). The state must
// be at that frame: sim.state.step == frame * steps_per_frame.
void save_checkpoint(const std::filesystem::path& dir, const Scene& scene, const Timeline& tl,
                     const Simulation& sim, std::int64_t frame);

// Frames of the checkpoint files in `dir`, ascending. Throws io::BadInput when `dir` is not a
// directory.
std::vector<std::int64_t> checkpoint_frames(const std::filesystem::path& dir);

// The checkpoint in `dir` with the largest frame <= `frame`, checked against this run (another
// scene, build, integrator, step or frame rate; a state that does not fit the model), or nothing
// when there is none at or before `frame`. Throws CheckpointError naming the file and why it
// cannot be used.
std::optional<ResumePoint> nearest_checkpoint(const std::filesystem::path& dir, std::int64_t frame,
                                              const Scene& scene, const Timeline& tl,
                                              const Simulation& sim);

} // namespace tumble::app
