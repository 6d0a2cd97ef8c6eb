#pragma once
// PNG outputs: a numbered sequence (one file per frame) or a single still.
#include "io/atomic_file.h"
#include "render/frame_sink.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tumble::render {

// A file name with one printf-style integer conversion, e.g. "frames/%06d.png": %d, or %Nd /
// %0Nd for a minimum width of N padded with spaces / zeros. "%%" stands for a literal '%'. The
// number is formatted here, never by printf, so a user's file name is never a format string.
struct FramePattern {
    std::string prefix; // everything before the conversion, with %% already turned into %
    std::string suffix; // everything after it
    int width = 0;      // minimum number of characters
    bool zero_pad = false;
    std::string text; // the pattern as given, for messages

    std::string name(std::int64_t frame) const;

    // Parses `text`. Returns nothing when it has no conversion at all; throws SinkError when a
    // '%' is not part of exactly one integer conversion in the file name (not in a directory).
    static std::optional<FramePattern> parse(const std::string& text);
    // dir/000000.png, dir/000001.png ... (six digits, the default for a directory output).
    static FramePattern in_directory(const std::filesystem::path& dir);
    // The frame files an output names, as open_sink() reads it: a folder ("frames/", or an
    // existing directory) gives in_directory(), a name with a conversion its pattern; a single
    // file gives nothing. Throws SinkError for a malformed pattern (as parse()).
    static std::optional<FramePattern> of_output(const std::string& output);
    // The files already in the pattern's folder that it could have written: the prefix, one or
    // more digits (at least `width` when zero-padded), the suffix. Sorted by name.
    std::vector<std::filesystem::path> existing_frames() const;
};

// Frame k goes to pattern.name(k), each file written atomically by write_png as it arrives.
class PngSequenceSink final : public FrameSink {
  public:
    // Creates the directory of the pattern if missing, with its parents. Throws SinkError when it
    // cannot, when the directory is not writable, or when it already holds frames of the pattern
    // and options.overwrite is off (with it, those files, and only those, are removed first).
    PngSequenceSink(FramePattern pattern, const SinkOptions& options);
    ~PngSequenceSink() override { abort(); }

    void write(const Image& image) override;
    void finish() override;
    void abort() noexcept override;
    std::string describe() const override { return pattern_.text; }
    std::int64_t frames_written() const override { return frames_; }

  private:
    FramePattern pattern_;
    SinkOptions options_;
    std::filesystem::path created_directory_; // set when this sink created it
    std::int64_t frames_ = 0;
    bool done_ = false;
};

// Exactly one frame, encoded into a temporary file by write() and renamed into place by finish().
class PngStillSink final : public FrameSink {
  public:
    PngStillSink(const std::filesystem::path& path, const SinkOptions& options);
    ~PngStillSink() override { abort(); }

    void write(const Image& image) override;
    void finish() override;
    void abort() noexcept override;
    std::string describe() const override { return file_.final_path().string(); }
    std::int64_t frames_written() const override { return frames_; }

  private:
    io::AtomicFile file_;
    SinkOptions options_;
    std::int64_t frames_ = 0;
    bool done_ = false;
};

} // namespace tumble::render
