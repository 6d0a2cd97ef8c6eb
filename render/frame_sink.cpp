// What every sink shares (frame_sink.h): the frame check, and one way to finish or refuse.
#include "render/frame_sink.h"

#include "io/atomic_file.h"

namespace tumble::render {

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

void check_open(const FrameSink& sink, bool done) {
    if (done) throw SinkError("'" + sink.describe() + "' is already finished");
}

void finish_sink(FrameSink& sink, bool& done, std::int64_t frames,
                 const std::function<void()>& complete) {
    check_open(sink, done);
    try {
        if (frames == 0) throw SinkError("no frame was written to '" + sink.describe() + "'");
        complete();
    } catch (const io::FileError& e) {
        sink.abort();
        throw SinkError(e.what());
    } catch (...) {
        sink.abort();
        throw;
    }
    done = true;
}

} // namespace detail

} // namespace tumble::render
