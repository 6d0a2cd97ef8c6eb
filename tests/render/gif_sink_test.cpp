// Animated GIF output (issue 14): one palette per video through libavfilter. Decoded back here
// with libavformat/libavcodec: every frame is there, at its size, and close to what was written
// (256 colours with error diffusion); above 50 fps every n-th frame is kept so that browsers play
// it at its speed; an empty or aborted GIF leaves nothing behind.
#include "render/gif_sink.h"
#include "render/open_sink.h"

#include "test_support.h"

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <cmath>
#include <memory>
#include <vector>

namespace tumble::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_artifact_dir;
using test::list_dir;

struct Decoded {
    std::vector<Image> frames;
    double duration = 0.0; // s
};

Decoded decode_gif(const fs::path& path) {
    Decoded out;
    AVFormatContext* f = nullptr;
    EXPECT_EQ(avformat_open_input(&f, path.c_str(), nullptr, nullptr), 0);
    if (!f) return out;
    std::unique_ptr<AVFormatContext, void (*)(AVFormatContext*)> format(
        f, [](AVFormatContext* c) { avformat_close_input(&c); });
    EXPECT_GE(avformat_find_stream_info(f, nullptr), 0);
    const AVCodecParameters* par = f->streams[0]->codecpar;
    EXPECT_EQ(par->codec_id, AV_CODEC_ID_GIF);
    const AVCodec* decoder = avcodec_find_decoder(par->codec_id);
    std::unique_ptr<AVCodecContext, void (*)(AVCodecContext*)> codec(
        avcodec_alloc_context3(decoder), [](AVCodecContext* c) { avcodec_free_context(&c); });
    avcodec_parameters_to_context(codec.get(), par);
    EXPECT_GE(avcodec_open2(codec.get(), decoder, nullptr), 0);
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    auto receive = [&] {
        while (avcodec_receive_frame(codec.get(), frame) == 0) {
            EXPECT_EQ(frame->format, AV_PIX_FMT_BGRA); // FFmpeg's GIF decoder gives 32-bit BGRA
            Image image(frame->width, frame->height);
            for (int y = 0; y < frame->height; ++y)
                for (int x = 0; x < frame->width; ++x) {
                    const std::uint8_t* p = frame->data[0] + y * frame->linesize[0] + 4 * x;
                    std::uint8_t* q = image.row(y) + 3 * x;
                    q[0] = p[2], q[1] = p[1], q[2] = p[0];
                }
            out.frames.push_back(std::move(image));
        }
    };
    while (av_read_frame(f, packet) >= 0) {
        avcodec_send_packet(codec.get(), packet);
        av_packet_unref(packet);
        receive();
    }
    avcodec_send_packet(codec.get(), nullptr);
    receive();
    if (f->duration > 0) out.duration = double(f->duration) / AV_TIME_BASE;
    av_frame_free(&frame);
    av_packet_free(&packet);
    return out;
}

// Peak signal-to-noise ratio of b against a, dB.
double psnr(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        const double d = double(a.rgb[i]) - double(b.rgb[i]);
        sum += d * d;
    }
    const double mse = sum / double(a.rgb.size());
    return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

TEST(GifSink, EveryFrameDecodesCloseToWhatWasWritten) {
    const fs::path dir = fresh_artifact_dir();
    SinkOptions options;
    options.width = 96, options.height = 64, options.fps = 24;
    std::vector<Image> written;
    auto sink = open_sink((dir / "clip.gif").string(), options);
    for (int k = 0; k < 12; ++k) {
        written.push_back(test::rendered_like(96, 64, 2.0 * k));
        sink->write(written.back());
    }
    sink->finish();
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"clip.gif"}); // no spool, no temporary
    const Decoded d = decode_gif(dir / "clip.gif");
    ASSERT_EQ(d.frames.size(), 12u);
    double worst = 99.0;
    for (std::size_t k = 0; k < 12; ++k) {
        ASSERT_EQ(d.frames[k].width, 96);
        worst = std::min(worst, psnr(written[k], d.frames[k]));
    }
    std::printf("[measured] worst frame PSNR %.1f dB (bound 30)\n", worst);
    EXPECT_GT(worst, 30.0);
    EXPECT_NEAR(d.duration, 0.5, 0.02); // 12 frames at 24 fps, in centisecond delays
}

TEST(GifSink, AboveFiftyFpsEveryNthFrameIsKept) {
    const fs::path dir = fresh_artifact_dir();
    SinkOptions options;
    options.width = 32, options.height = 24, options.fps = 60;
    auto sink = open_sink((dir / "fast.gif").string(), options);
    const auto* gif = dynamic_cast<const GifSink*>(sink.get());
    ASSERT_NE(gif, nullptr);
    EXPECT_EQ(gif->stride(), 2); // 60 fps plays at 30: delays of 3.33 cs, not 1.67
    for (int k = 0; k < 60; ++k) sink->write(test::rendered_like(32, 24, k));
    sink->finish();
    const Decoded d = decode_gif(dir / "fast.gif");
    EXPECT_EQ(d.frames.size(), 30u);
    EXPECT_NEAR(d.duration, 1.0, 0.02);
}

TEST(GifSink, NoFrameOrAbortLeavesNothing) {
    const fs::path dir = fresh_artifact_dir();
    SinkOptions options;
    options.width = 32, options.height = 24, options.fps = 30;
    {
        auto sink = open_sink((dir / "empty.gif").string(), options);
        EXPECT_THROW(sink->finish(), SinkError);
    }
    {
        auto sink = open_sink((dir / "aborted.gif").string(), options);
        sink->write(test::rendered_like(32, 24));
        sink->abort();
    }
    EXPECT_TRUE(list_dir(dir).empty());
}

} // namespace
} // namespace tumble::render
