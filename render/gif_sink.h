#pragma once
// Animated GIF (*.gif) for documentation pages and chat, through libavfilter: one palette of 256
// colours chosen for the whole video, then every frame mapped onto it with error diffusion. The
// palette needs every frame before the first can be written, so this sink keeps the frames, as
// raw RGB, in a spool file beside the output (".NAME.<pid>.partial.frames", deleted when done)
// and makes the GIF in finish():
//   1. buffer -> palettegen (stats_mode=full: the colours of all frames, weighted alike)
//   2. buffer + the palette -> paletteuse (dither=sierra2_4a) -> GIF encoder -> GIF muxer
// GIF frame delays are whole centiseconds and browsers slow down delays under 2 cs to 10 cs, so
// above 50 fps every n-th frame is kept (n = ceil(fps / 50): 60 fps plays at 30). Written, like
// every output, under a temporary name and renamed when complete; a regular file only (a GIF
// cannot be streamed: it is made after the last frame).
#include "io/atomic_file.h"
#include "render/frame_sink.h"

#include <cstdio>
#include <filesystem>

namespace tumble::render {

class GifSink final : public FrameSink {
  public:
    // Throws SinkError for a stream output, missing dimensions or fps, or an unwritable folder.
    GifSink(const std::filesystem::path& output, const SinkOptions& options);
    ~GifSink() override;

    void write(const Image& image) override;
    void finish() override;
    void abort() noexcept override;
    std::string describe() const override { return file_.final_path().string(); }
    std::string note() const override; // the frame rate it plays at, when it is not the run's
    std::int64_t frames_written() const override { return frames_; }

    // Frames kept of every `stride` written, and the GIF's frame rate (fps / stride).
    int stride() const { return stride_; }

  private:
    void encode(); // the two passes of finish()

    io::AtomicFile file_;
    SinkOptions options_;
    std::filesystem::path spool_path_;
    std::FILE* spool_ = nullptr;
    int stride_ = 1;
    std::int64_t frames_ = 0, kept_ = 0;
    bool done_ = false;
};

} // namespace tumble::render
