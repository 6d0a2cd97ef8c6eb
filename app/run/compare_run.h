#pragma once
// `tumble render --compare euler,rk4,...` and the Python module's render(compare=[...]): the same
// scene stepped by several integrators, drawn side by side in one video (side_by_side.h). The
// overlay is on unless the request turns it off: it names the integrator and shows its energy
// drift since t = 0.
//
// Frames are made in a plain loop (simulate, draw each tile, write), not the threaded pipeline of
// pipeline.h: a comparison is for looking at, not for speed.
#include "app/run/render_request.h"
#include "app/run/run_request.h"
#include "app/run/side_by_side.h"
#include "app/scene/scene.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tumble::app {

// Refuses what a comparison cannot take, before the scene is loaded: an --integrator (the
// comparison names its integrators). Throws SceneError.
void check_compare_request(const RunRequest& run);

struct CompareRun {
    std::vector<SideBySide::LaneResult> lanes;
    std::string output;       // what the sink wrote (FrameSink::describe())
    std::string sink_note;    // FrameSink::note(): a GIF's frame rate when it is not the run's
    std::int64_t frames = 0;  // written
    bool interrupted = false; // stopped by Ctrl-C (io/interrupt.h); the video plays
    int cols = 0, rows = 0;   // tiles
    int tile_width = 0, tile_height = 0;
};

// Draws `request.compare`'s integrators side by side for `scene` (loaded, with the run's
// overrides applied: apply_request()) into request.output (default "<scene>-compare.mp4"), or
// only request.frame / request.time. Notes (a time between frames) go to `note`; a progress bar
// shows on a terminal unless `quiet`. Throws SceneError for bad names, io::BadInput for an output
// that cannot be opened, and what stepping and drawing throw.
CompareRun render_compare(Scene scene, RenderRequest request, int threads, bool quiet,
                          const std::function<void(const std::string&)>& note);

} // namespace tumble::app
