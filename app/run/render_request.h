#pragma once
// What a render is asked beyond its scene file: the picture switches of `tumble render` (and of
// the Python module's keyword arguments), the output and its encoding, with one meaning and one
// set of error messages for both (run_request.h is the same for the physics' overrides). What the
// commands that draw (render, render --compare, the render benchmark, the Python module) make of
// them: the scene's picture settings with the overrides applied, the output's name, and its sink.
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "render/frame_sink.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tumble::app {

struct RenderRequest {
    std::string output; // empty: "<scene name>.mp4"
    std::optional<int> width, height, fps;
    std::optional<std::int64_t> frame; // render only this frame (to a still .png)
    std::optional<double> time;        // or the frame shown at this time, s (resolve_time)
    int crf = 18;
    // Encoder preset; unset: "medium", or "ultrafast" with --preview (video_preset()).
    std::optional<std::string> preset;
    // Picture switches; unset ones keep the scene's render settings.
    bool preview = false; // 640x360 (unless --width/--height), no shadows, AA, AO or reflections
    std::optional<bool> shadows, soft_shadows, ambient_occlusion, reflections, antialiasing,
        overlay, axes, vectors;
    // Teaching overlays; unset ones keep the scene's.
    std::optional<std::vector<std::string>> chart; // quantity names
    std::optional<std::string> chart_body, poinsot, overlay_body, trail_axis;
    // --camera POSITION:TARGET[:FOV], auto or poinsot (app/scene/camera_rig.h:
    // read_camera_option); unset: the scene's, or the construction's with --poinsot.
    std::optional<std::string> camera;
    std::optional<double> chart_window, trail_seconds;
    std::optional<bool> trails;
    bool overwrite = false; // a frame folder may hold an earlier run's frames: remove them first
    bool quiet = false;     // no warnings on stderr (a --poinsot body that may feel a torque)
    // Integrators drawn side by side, each stepping its own copy of the scene (compare_run.h).
    std::vector<std::string> compare;
};

// What a run adds to its sink's options: the frames it draws when it is a shard
// (SinkOptions::first_frame, end_frame) and the video's tumble-shard tag (app/cluster/shard_tag.h).
struct RunOutput {
    std::int64_t first_frame = 0, end_frame = -1;
    std::string comment;
};

// --width/--height/--fps, --camera and the picture switches (--preview, --[no-]shadows,
// --[no-]aa, --[no-]overlay, --[no-]axes) applied to the scene's render settings. Throws
// SceneError.
void apply_render_overrides(const RenderRequest& request, Scene& scene);

// The encoder preset of a run: --preset if given, else "ultrafast" for --preview (a quick look:
// measured, veryfast encoding made the 640x360 preview 1.58x slower than drawing alone, ultrafast
// keeps it near the renderer's pace) and "medium" otherwise. Measured (scripts/bench-encoder.sh,
// bench/results/vm/encoder.csv: 2 s of three built-in scenes at 1280x720, decoded and compared
// with the lossless frames in RGB): at CRF 18, medium gains 1.0-1.4 dB PSNR over veryfast (SSIM
// 0.9954-0.9968 against 0.9935-0.9951) for 10-23% more bits, a better trade than veryfast at a
// lower CRF (CRF 15 veryfast: as good, 12-19% more bits than medium at 18); the 600-frame default
// demo takes 28.6 s end to end against 25.9 s (1.10x), the renderer being the slow stage.
std::string video_preset(const RenderRequest& request);

// --time T: sets `frame` to the frame shown at t = T, K = round(T fps). Returns a note when T
// lies between frame times ("t = 1.01 s is between frames at 60 fps: frame 61, t = 1.01667 s"),
// else "". Throws SceneError for a negative or non-finite T.
std::string resolve_time(RenderRequest& request, const Timeline& tl);

// Throws SceneError when --frame (or --time) names a frame outside the video.
void check_frame_index(const RenderRequest& request, const Timeline& tl);

// --output, or "<scene name><suffix>.mp4" (app/scene/scene.h: scene_name), or for --frame K
// "<scene name><suffix>_<K, six digits>.png". Throws
// io::BadInput when the output cannot take this run: --frame writes one still, a .png.
std::string output_name(const RenderRequest& request, const Scene& scene,
                        const std::string& suffix = "");

// The sink for `output` at the scene's size and frame rate with the request's quality settings,
// creating the output's folder first (not for a name with a %d pattern) and removing what killed
// runs left for it (stale_temporaries.h; said on stderr unless `quiet`). An output that cannot be
// opened (unknown type, odd size for H.264, a folder that cannot be made) is bad input: throws
// io::BadInput. Errors while writing later are failed runs (render::SinkError).
// MP4s get a key frame every two seconds (key_interval.h), where the encoder starts afresh, so
// that a video can be split into shards there.
std::unique_ptr<render::FrameSink> open_render_sink(const RenderRequest& request,
                                                    const Scene& scene, const std::string& output,
                                                    const RunOutput& run, bool quiet);

} // namespace tumble::app
