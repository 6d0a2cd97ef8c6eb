// What a user sees in a video is every rendered frame, once each, in order, at its time: the MP4,
// WebM and GIF that `tumble render` writes are decoded here (decoded_video.h: libavcodec, and
// libswscale with the stream's colour tags, as a player does) and every decoded picture is matched
// against every frame of the run, drawn independently of the pipeline and its sinks: each frame k
// a still of its own (still() below: a fresh prepared run stepped to t = k / fps, one renderer).
//
// A decoded picture D_i must be nearest (by mean squared error over the RGB values) to its own
// frame P_own, and by a clear margin. For a lossy codec, D_i = P_own + n with coding noise n, and
// for any other frame P_j:
//   margin = (mse(D_i, P_j) - mse(D_i, P_own)) / mse(P_own, P_j) = 1 + 2 <n, P_own - P_j> / |P_own
//   - P_j|^2
// which is 1 when the noise has nothing of the difference between the frames, 0 when D_i lies
// half way between P_own and P_j, and -1 when D_i is P_j (a repeated, dropped or swapped frame).
// So a margin bound fails a drop, a repeat or a reorder whatever the frames' difference, while
// the coding noise is judged apart by the PSNR against the own frame. Both bounds come from
// measurement on this build (printed beside them); the frames of the run are checked distinct,
// so that a repeat could not pass unseen.
//
// A GIF keeps every n-th frame above 50 fps, n = ceil(fps / 50) (browsers slow down frame delays
// under 2 centiseconds; docs and render/gif_sink.h): at 60 fps the GIF holds frames 0, 2, 4, ...
// and plays at 30 fps.
#include "app/run/auto_camera.h"
#include "app/run/frame_source.h"
#include "app/run/prepare_run.h"
#include "app/run/render_frames.h"
#include "app/scene/scene.h"
#include "render/png_io.h"
#include "render/renderer.h"
#include "support/cli_runner.h"
#include "support/decoded_video.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace tumble::test {
namespace {

// The default scene (a book flipping in the air, balls bouncing: something moves in every
// frame), small and short.
constexpr int kWidth = 320, kHeight = 180, kFps = 60, kFrames = 30;
const std::string kRender = "render default --width 320 --height 180 --fps 60 --duration 0.5 -q";

// Bounds, from the worst values measured on this build (Debian 12: FFmpeg 5.1, x264 164,
// libvpx 1.12; the default --crf of each) with room for other versions of the encoders. The
// least margins come where two frames differ least (the balls start at rest: frames 0 and 1 differ
// by an MSE of 3.1, about the coding noise's 4 to 6): measured 0.42 for the MP4's picture 1
// (0.72 to 0.95 once the balls move), 0.65 for the WebM, 0.98 for the GIF. A bound of 0.25 keeps
// a decoded picture within 3/8 of the way to any other frame; a repeat or a drop gives -1.
struct Bounds {
    double psnr;    // dB, least over decoded frames against their own frame
    double margin;  // least over decoded frames and other frames
    double seconds; // largest |presentation time - frame time|
};

// Frame k alone: a fresh run (app/run/prepare_run.h) stepped to t = k / fps and drawn, without
// the pipeline or a sink.
render::Image still(const app::Scene& given, int k, render::Renderer& renderer) {
    app::PreparedRun run = app::prepare_run(given);
    app::frame_automatically(run.scene, run.timeline);
    app::FrameSource source(run.scene, run.timeline, run.sim, k, k);
    render::SceneView view;
    source.next(view);
    render::Image image;
    renderer.draw(view, image);
    return image;
}

// Frame k of the run at t = k / fps, each drawn on its own, outside the pipeline.
const std::vector<render::Image>& rendered_frames() {
    static const std::vector<render::Image> frames = [] {
        app::Scene scene = app::load_scene_argument("default");
        scene.render.width = kWidth, scene.render.height = kHeight, scene.render.fps = kFps;
        scene.duration = double(kFrames) / kFps;
        render::Renderer renderer(app::render_options(scene.render));
        std::vector<render::Image> out;
        for (int k = 0; k < kFrames; ++k) out.push_back(still(scene, k, renderer));
        return out;
    }();
    return frames;
}

double mse(const render::Image& a, const render::Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        const double d = double(a.rgb[i]) - double(b.rgb[i]);
        sum += d * d;
    }
    return sum / double(a.rgb.size());
}

double psnr(double mean_squared_error) {
    return mean_squared_error == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mean_squared_error);
}

// Renders the run to `file` through the real binary and holds each decoded picture to its own
// frame, every `stride`-th of the run.
void expect_every_frame_once_in_order(const std::string& file, const std::string& codec, int stride,
                                      const Bounds& bounds) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, kRender + " -o " + file);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const DecodedVideo video = decode_video(dir / file);
    EXPECT_EQ(video.codec, codec);
    const std::vector<render::Image>& frames = rendered_frames();
    for (std::size_t a = 0; a + 1 < frames.size(); ++a) // a repeat must be seen
        ASSERT_GT(mse(frames[a], frames[a + 1]), 0.0) << "frames " << a << " and " << a + 1;
    const std::size_t expected = (frames.size() + std::size_t(stride) - 1) / std::size_t(stride);
    EXPECT_EQ(video.frames.size(), expected) << "decoded pictures, one per kept frame";

    double worst_psnr = 99.0, worst_margin = std::numeric_limits<double>::infinity();
    double worst_seconds = 0.0;
    for (std::size_t i = 0; i < video.frames.size(); ++i) {
        const render::Image& d = video.frames[i];
        ASSERT_EQ(d.width, kWidth);
        ASSERT_EQ(d.height, kHeight);
        const std::size_t own = i * std::size_t(stride);
        if (own >= frames.size()) break; // an extra picture: counted above
        worst_seconds = std::max(worst_seconds, std::abs(video.seconds[i] - double(own) / kFps));
        std::vector<double> to(frames.size());
        std::size_t nearest = 0;
        for (std::size_t j = 0; j < frames.size(); ++j) {
            to[j] = mse(d, frames[j]);
            if (to[j] < to[nearest]) nearest = j;
        }
        EXPECT_EQ(nearest, own) << "decoded picture " << i << " (at " << video.seconds[i]
                                << " s) looks most like frame " << nearest << ", not frame " << own;
        worst_psnr = std::min(worst_psnr, psnr(to[own]));
        for (std::size_t j = 0; j < frames.size(); ++j) {
            if (j == own) continue;
            const double margin = (to[j] - to[own]) / mse(frames[own], frames[j]);
            if (margin < bounds.margin)
                ADD_FAILURE() << "decoded picture " << i << " is only " << margin
                              << " of the way from frame " << j << " to its own frame " << own
                              << " (bound " << bounds.margin << ")";
            worst_margin = std::min(worst_margin, margin);
        }
    }
    std::printf("[decoded] %s: %zu pictures for %zu frames (one kept of every %d)\n", file.c_str(),
                video.frames.size(), frames.size(), stride);
    TUMBLE_MEASURED(worst_psnr, bounds.psnr);
    TUMBLE_MEASURED(worst_margin, bounds.margin);
    TUMBLE_MEASURED(worst_seconds, bounds.seconds);
    EXPECT_GE(worst_psnr, bounds.psnr);
    EXPECT_LE(worst_seconds, bounds.seconds);
}

// The reference itself: a lossless PNG sequence of the pipeline holds exactly the stills.
TEST(DecodedFrames, PngSequenceHoldsEveryFrameExactly) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, kRender + " -o frames/");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<render::Image>& frames = rendered_frames();
    EXPECT_EQ(files_in(dir).size(), frames.size());
    for (std::size_t k = 0; k < frames.size(); ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "frames/%06zu.png", k);
        EXPECT_TRUE(render::read_png(dir / name).rgb == frames[k].rgb)
            << name << " is not the still of frame " << k;
    }
}

TEST(DecodedFrames, Mp4ShowsEveryFrameOnceInOrder) {
    // Measured: PSNR 39.8 dB at worst (crf 18); times exact (time base 1/fps).
    expect_every_frame_once_in_order("out.mp4", "h264", 1, {36.0, 0.25, 1e-9});
}

TEST(DecodedFrames, WebmShowsEveryFrameOnceInOrder) {
    // Measured: PSNR 42.8 dB at worst. WebM keeps time in milliseconds: frame times at 60 fps are
    // rounded to 1 ms (measured 0.33 ms off at most).
    expect_every_frame_once_in_order("out.webm", "vp9", 1, {39.0, 0.25, 0.0005});
}

TEST(DecodedFrames, GifShowsEveryOtherFrameAt30FpsInOrder) {
    // 60 fps: n = ceil(60 / 50) = 2. GIF delays are whole centiseconds (3 or 4 for 3.33: measured
    // 3.3 ms off at most). Measured: PSNR 51.7 dB at worst (the default scene has few colours).
    expect_every_frame_once_in_order("out.gif", "gif", 2, {45.0, 0.25, 0.01});
}

} // namespace
} // namespace tumble::test
