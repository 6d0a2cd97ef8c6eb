#pragma once
// H.264 video in an MP4 file, through libavformat/libavcodec (libx264) and libswscale.
//
// What the file holds, and why:
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
// The file is written as ".NAME.<pid>.partial" in the same directory and renamed in finish().
#include "render/atomic_file.h"
#include "render/frame_sink.h"

#include <filesystem>
#include <memory>

namespace tumble::render {

class Mp4Sink final : public FrameSink {
  public:
    // Opens the encoder and the temporary file. Throws SinkError for odd or missing dimensions,
    // bad fps/crf/preset, an unwritable directory, or a missing libx264.
    Mp4Sink(const std::filesystem::path& output, const SinkOptions& options);
    ~Mp4Sink() override;

    void write(const Image& image) override;
    void finish() override;
    void abort() noexcept override;
    std::string describe() const override { return file_.final_path().string(); }
    std::int64_t frames_written() const override { return frames_; }

  private:
    struct Encoder; // the libav objects; kept out of this header
    AtomicFile file_;
    SinkOptions options_;
    std::unique_ptr<Encoder> encoder_;
    std::int64_t frames_ = 0;
    bool done_ = false; // finished or aborted
};

} // namespace tumble::render
