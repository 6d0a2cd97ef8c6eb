#pragma once
// Where rendered frames go: the sink interface every output implements (a video, a GIF, PNG
// frames, a still, nothing), its options, and what they share. open_sink.h picks one from an
// output name. Every file is written under a temporary name in the same directory and renamed
// only when it is complete, so an interrupted or failed run never leaves a half-written file.
#include "render/image.h"
#include "render/png_io.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace tumble::render {

struct SinkError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct SinkOptions {
    int width = 0;  // required for *.mp4; for PNG sinks 0 means "whatever the first frame has"
    int height = 0; // (every frame must then have the same size)
    int fps = 60;   // frames per second; the container time base is 1/fps
    int crf = 18;   // H.264 constant rate factor (0 lossless .. 51 worst)
    std::string preset = "medium"; // libx264 preset, ultrafast .. placebo (app/run/render_request.h)
    // libx264 threads. The count is part of the output: x264 records its settings (threads=N)
    // in the stream, and frame threads limit motion search to rows other threads have
    // finished; measured on fast vertical motion, 3 threads (x264's automatic choice on 2
    // cores) gave a quite different stream from 1 or 2. A fixed count therefore gives the same
    // bytes on every machine for the same frames; 0 lets x264 pick 1.5 per core, and the bytes
    // then depend on the machine. On a 2-core machine 1 thread measured as fast as 2 and faster
    // than 3 at 1280x720, and it leaves the other core to the renderer.
    int threads = 1;
    // Extra libx264 settings, "key=value:key=value" (x264 --fullhelp), for experiments. Added
    // after the sink's own "cpu-independent=1" (see video_sink.h), so they can override it.
    std::string x264_params;
    PngWriteOptions png;    // encoder and zlib level of PNG sinks
    bool overwrite = false; // PNG sequence: replace frames of the pattern already in the folder
    // MP4: x264 is closed and opened afresh every `key_interval` frames of the whole run (0: one
    // encoder for the whole file), so that each run of key_interval frames is encoded knowing
    // nothing of the others (video_sink.h says why) and a shard's video holds the same packets
    // as the same frames of a whole render.
    int key_interval = 0;
    // A shard of a longer run (`tumble render --frames A:B`): the frames written are A..B-1 of the
    // whole run (first_frame = A, a multiple of key_interval; end_frame = B). A PNG sequence names
    // frame k by its index in the whole run, and refuses (or with `overwrite` removes) only the
    // existing frames of its own range, since other shards fill the rest of the folder.
    // end_frame -1: the whole run, starting at first_frame.
    std::int64_t first_frame = 0;
    std::int64_t end_frame = -1;
    // Video files: the container's "comment" tag (MP4 and WebM), e.g. what `tumble join` checks.
    std::string comment;
};

class FrameSink {
  public:
    virtual ~FrameSink() = default;
    // Frame k is shown at t = k / fps. Frames arrive in order starting at 0. Throws SinkError
    // when the image has the wrong size or cannot be written; the caller then calls abort() (or
    // lets the destructor do it).
    virtual void write(const Image& image) = 0;
    // Completes the output (trailer, rename) so it plays or opens. Call once. Throws SinkError,
    // after deleting the partial output, when that fails or when no frame was written (there is
    // nothing to save).
    virtual void finish() = 0;
    // Deletes whatever was written so far (for a PNG sequence: the frames this sink wrote, and
    // the directory if the sink created it and it is now empty). Called on errors; the
    // destructor calls it if neither finish() nor abort() ran. Never throws.
    virtual void abort() noexcept = 0;
    // Final path(s) for messages, e.g. "out/default.mp4" or "frames/%06d.png".
    virtual std::string describe() const = 0;
    // What the output keeps differently from the frames it was given, for the run's summary
    // (a GIF above 50 fps keeps every n-th frame); "" when it keeps them all as they are.
    virtual std::string note() const { return ""; }
    virtual std::int64_t frames_written() const = 0;
};

namespace detail {
// Throws SinkError naming `output` unless `image` is non-empty, its pixel buffer matches its size,
// and it is `width` x `height` (when those are > 0).
void check_frame(const std::string& output, const Image& image, int width, int height);

// What every sink's write() checks first: the output is not finished (or aborted) yet.
void check_open(const FrameSink& sink, bool done);

// The one way a sink finishes: refuses a second finish() and an output without frames, runs
// `complete` (the encoder's last frames, the trailer, the rename into place) and, if anything
// fails, deletes the partial output with sink.abort() before rethrowing (an io::FileError as a
// SinkError). Sets `done` once the output is complete.
void finish_sink(FrameSink& sink, bool& done, std::int64_t frames,
                 const std::function<void()>& complete);
} // namespace detail

} // namespace tumble::render
