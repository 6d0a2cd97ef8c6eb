#pragma once
// Video files through libavformat/libavcodec and libswscale, chosen by the output's extension:
//   .mp4   H.264 (libx264) in MP4: the default, for slides, players and browsers.
//   .webm  VP9 (libvpx) in WebM: for documentation pages that want an open format. --crf is
//          VP9's quality (0..63, lower is better); --preset picks libvpx's speed (ultrafast ..
//          faster: realtime, cpu-used 8; fast, medium: good, cpu-used 4; slower ones: cpu-used 2).
//          WebM keeps time in milliseconds, so at 60 fps frame times are rounded to 1 ms.
//
// What an MP4 holds, and why (WebM likewise where it applies):
//  * yuv420p, 8 bits: the only H.264 format every browser and phone decodes. Chroma is stored at
//    half resolution in both directions, hence even width and height are required.
//  * BT.709 colour, limited ("TV", 16..235) range, tagged as such in the stream: the HD
//    standard, and what players assume for untagged HD video anyway, so colours match everywhere.
//  * time base 1/fps and pts = frame index: timestamps are exact integers, so the container's
//    frame rate is exactly fps and the duration exactly frames/fps (no 29.97-style drift).
//  * movflags=+faststart: the index ("moov") goes before the data, so a browser can start
//    playing before it has downloaded the whole file.
//  * Deterministic: the same frames and options give the same bytes, whatever SIMD the CPU has
//    (checked: plain C, SSE4, AVX2 and AVX-512 code paths give identical files):
//    - a fixed thread count (SinkOptions::threads);
//    - x264's cpu-independent=1: without it x264 picks some algorithms by CPU, and the C code
//      and the SIMD code gave different streams (measured: ~all bytes differ); with it they
//      match, at ~1% speed cost;
//    - SWS_BITEXACT for the RGB -> YUV conversion (same result from every SIMD path);
//    - no wall-clock time in the file (the MP4 creation time stays 0).
//    Different FFmpeg or x264 versions may still encode differently (and record their versions).
//  * Key frames (MP4, SinkOptions::key_interval K): x264 is drained and opened afresh at every
//    frame whose index in the whole run is a multiple of K, so each K frames are encoded by an
//    encoder that has seen no others, starting with an IDR picture. Key frames alone (x264's
//    keyint) would not do: x264's rate control carries history from frame to frame (the
//    quantiser of a frame follows the complexity of the frames before it, and an I frame's
//    follows the past P frames'), so the same frames would be coded differently after another
//    past. With fresh encoders a shard of frames A..B-1 (A a multiple of K) holds exactly the
//    packets of those frames in a whole render, and `tumble join` is a remux (app/cluster).
//    Timestamps run on across the restarts (pts = frame index in the file).
// The file is written as ".NAME.<pid>.partial" in the same directory and renamed in finish().
#include "io/atomic_file.h"
#include "render/frame_sink.h"

#include <filesystem>
#include <memory>

namespace tumble::render {

class VideoSink final : public FrameSink {
  public:
    // Opens the encoder and the temporary file. Throws SinkError for odd or missing dimensions,
    // bad fps/crf/preset, an unwritable directory, or a missing encoder.
    VideoSink(const std::filesystem::path& output, const SinkOptions& options);
    ~VideoSink() override;

    void write(const Image& image) override;
    void finish() override;
    void abort() noexcept override;
    std::string describe() const override { return file_.final_path().string(); }
    std::int64_t frames_written() const override { return frames_; }

  private:
    struct Encoder; // the libav objects; kept out of this header
    io::AtomicFile file_;
    SinkOptions options_;
    std::unique_ptr<Encoder> encoder_;
    std::int64_t frames_ = 0;
    bool done_ = false; // finished or aborted
};

// libavcodec and libx264 log to stderr at "info" level by default (CPU flags, statistics at the
// end of every encode). This lowers FFmpeg's process-wide log level to warnings and errors. The
// setting is global to the process, so only main() should call it, once, before encoding.
void quiet_video_logs();

} // namespace tumble::render
