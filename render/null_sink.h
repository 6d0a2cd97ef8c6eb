#pragma once
// The output "null": frames are checked and counted, none is kept. The baseline that shows what a
// real sink costs (`tumble render -o null --stats`, bench/render/render_bench).
#include "render/frame_sink.h"

namespace tumble::render {

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

} // namespace tumble::render
