// open_sink: picks the sink from the output name (see open_sink.h for the rules).
#include "render/open_sink.h"

#include "render/gif_sink.h"
#include "render/null_sink.h"
#include "render/png_sink.h"
#include "render/video_sink.h"

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

} // namespace tumble::render
