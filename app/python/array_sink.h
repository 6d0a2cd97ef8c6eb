#pragma once
// A frame sink that keeps frames in memory: frame i of a run goes to slot i of a caller's buffer
// of `capacity` frames of width x height x 3 bytes (a NumPy array's, uint8 (F, H, W, 3)). The
// pipeline's output stage copies each frame once, as a file sink would write it.
#include "render/frame_sink.h"

#include <cstdint>
#include <string>

namespace tumble::python {

class ArraySink : public render::FrameSink {
  public:
    ArraySink(std::uint8_t* data, int width, int height, std::int64_t capacity);
    void write(const render::Image& image) override;
    void finish() override {}
    void abort() noexcept override {}
    std::string describe() const override { return "a NumPy array"; }
    std::int64_t frames_written() const override { return written_; }

  private:
    std::uint8_t* data_;
    int width_, height_;
    std::int64_t capacity_, written_ = 0;
};

} // namespace tumble::python
