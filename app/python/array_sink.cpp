#include "app/python/array_sink.h"

#include <cstring>

namespace tumble::python {

ArraySink::ArraySink(std::uint8_t* data, int width, int height, std::int64_t capacity)
    : data_(data), width_(width), height_(height), capacity_(capacity) {}

void ArraySink::write(const render::Image& image) {
    render::detail::check_frame(describe(), image, width_, height_);
    if (written_ == capacity_)
        throw render::SinkError("a NumPy array of " + std::to_string(capacity_) +
                                " frames: one frame too many");
    const std::size_t bytes = std::size_t(width_) * std::size_t(height_) * 3;
    std::memcpy(data_ + std::size_t(written_) * bytes, image.rgb.data(), bytes);
    ++written_;
}

} // namespace tumble::python
