// open_sink: picks the sink from the output name (see frame_sink.h for the rules).
#include "render/frame_sink.h"

#include "render/gif_sink.h"
#include "render/png_sink.h"
#include "render/video_sink.h"

extern "C" {
#include <libavutil/log.h>
}

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace tumble::render {

namespace fs = std::filesystem;

namespace {

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

const char* const kSupported =
    "supported outputs: NAME.mp4 (H.264 video), NAME.webm (VP9 video), NAME.gif (animated GIF, "
    "one palette per video), NAME.png (one still), a "
    "directory such as "
    "frames/ (PNG sequence 000000.png, 000001.png ...), a pattern such as frames/%06d.png, or "
    "null (draw and discard, for timing)";

// Checks and counts frames, keeps none: the baseline that shows what a real sink costs.
class NullSink final : public FrameSink {
  public:
    explicit NullSink(const SinkOptions& options) : options_(options) {}
    void write(const Image& image) override {
        detail::check_frame("null", image, options_.width, options_.height);
        ++frames_;
    }
    void finish() override {
        if (frames_ == 0) throw SinkError("null: no frame was written");
    }
    void abort() noexcept override {}
    std::string describe() const override { return "null (frames discarded)"; }
    std::int64_t frames_written() const override { return frames_; }

  private:
    SinkOptions options_;
    std::int64_t frames_ = 0;
};

} // namespace

std::unique_ptr<FrameSink> open_sink(const std::string& output, const SinkOptions& options) {
    if (output.empty()) throw SinkError(std::string("no output given; ") + kSupported);
    if (output == "null") return std::make_unique<NullSink>(options);
    const std::string ext = lowercase(fs::path(output).extension().string());
    if (std::optional<FramePattern> pattern = FramePattern::of_output(output)) {
        if (!lowercase(pattern->suffix).ends_with(".png")) {
            throw SinkError("cannot write '" + output + "': numbered outputs are PNG only (" +
                            "e.g. frames/%06d.png); " + kSupported);
        }
        return std::make_unique<PngSequenceSink>(std::move(*pattern), options);
    }
    if (ext == ".mp4" || ext == ".webm") return std::make_unique<VideoSink>(output, options);
    if (ext == ".png") return std::make_unique<PngStillSink>(output, options);
    if (ext == ".gif") return std::make_unique<GifSink>(output, options);
    throw SinkError("cannot write '" + output + "': unknown output type" +
                    (ext.empty() ? std::string() : " '" + ext + "'") + "; " + kSupported);
}

void quiet_video_logs() {
    av_log_set_level(AV_LOG_WARNING);
}

namespace detail {

void check_frame(const std::string& output, const Image& image, int width, int height) {
    const auto size = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
        throw SinkError("cannot write to '" + output + "': the frame is empty or its pixel " +
                        "buffer does not match its size " + size(image.width, image.height));
    }
    if ((width > 0 && image.width != width) || (height > 0 && image.height != height)) {
        throw SinkError("cannot write to '" + output + "': the frame is " +
                        size(image.width, image.height) + " but the output is " +
                        size(width, height));
    }
}

} // namespace detail

} // namespace tumble::render
