#pragma once
// A video file decoded the way a player shows it: every picture of its first video stream, in
// presentation order, with its presentation time, converted to 8-bit RGB by libswscale with the
// colour matrix and range the stream is tagged with (BT.709 limited range for Tumble's MP4 and
// WebM; a GIF's palette colours are RGB already). For tests that compare what a user sees with
// the frames that were rendered.
#include "render/image.h"

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace tumble::test {

struct DecodedVideo {
    std::string codec;                 // "h264", "vp9", "gif"
    std::vector<render::Image> frames; // in presentation order
    std::vector<double> seconds;       // each frame's presentation time
};

namespace detail {

// One decoded picture to RGB24, honouring its colour matrix and range (unspecified: BT.709,
// limited, what players assume for HD video).
inline render::Image to_rgb(const AVFrame* frame) {
    render::Image out(frame->width, frame->height);
    std::unique_ptr<SwsContext, void (*)(SwsContext*)> sws(
        sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                       frame->height, AV_PIX_FMT_RGB24,
                       SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr,
                       nullptr),
        sws_freeContext);
    if (!sws) {
        ADD_FAILURE() << "libswscale cannot convert pixel format " << frame->format;
        return out;
    }
    const bool yuv = frame->format == AV_PIX_FMT_YUV420P;
    if (yuv) {
        const int space =
            frame->colorspace == AVCOL_SPC_UNSPECIFIED ? AVCOL_SPC_BT709 : frame->colorspace;
        const int* matrix = sws_getCoefficients(space);
        const int full = frame->color_range == AVCOL_RANGE_JPEG;
        sws_setColorspaceDetails(sws.get(), matrix, full, matrix, 1, 0, 1 << 16, 1 << 16);
    }
    std::uint8_t* dst[4] = {out.rgb.data(), nullptr, nullptr, nullptr};
    const int dst_stride[4] = {3 * frame->width, 0, 0, 0};
    sws_scale(sws.get(), frame->data, frame->linesize, 0, frame->height, dst, dst_stride);
    return out;
}

} // namespace detail

inline DecodedVideo decode_video(const std::filesystem::path& path) {
    DecodedVideo out;
    AVFormatContext* opened = nullptr;
    if (avformat_open_input(&opened, path.c_str(), nullptr, nullptr) < 0) {
        ADD_FAILURE() << "libavformat cannot open " << path;
        return out;
    }
    std::unique_ptr<AVFormatContext, void (*)(AVFormatContext*)> format(
        opened, [](AVFormatContext* f) { avformat_close_input(&f); });
    EXPECT_GE(avformat_find_stream_info(format.get(), nullptr), 0);
    const int index = av_find_best_stream(format.get(), AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) {
        ADD_FAILURE() << "no video stream in " << path;
        return out;
    }
    const AVStream* stream = format->streams[index];
    out.codec = avcodec_get_name(stream->codecpar->codec_id);
    const AVCodec* decoder = avcodec_find_decoder(stream->codecpar->codec_id);
    std::unique_ptr<AVCodecContext, void (*)(AVCodecContext*)> codec(
        avcodec_alloc_context3(decoder), [](AVCodecContext* c) { avcodec_free_context(&c); });
    avcodec_parameters_to_context(codec.get(), stream->codecpar);
    if (avcodec_open2(codec.get(), decoder, nullptr) < 0) {
        ADD_FAILURE() << "cannot open the " << out.codec << " decoder";
        return out;
    }
    std::unique_ptr<AVPacket, void (*)(AVPacket*)> packet(av_packet_alloc(),
                                                          [](AVPacket* p) { av_packet_free(&p); });
    std::unique_ptr<AVFrame, void (*)(AVFrame*)> frame(av_frame_alloc(),
                                                       [](AVFrame* f) { av_frame_free(&f); });
    const auto receive = [&] {
        while (avcodec_receive_frame(codec.get(), frame.get()) == 0) {
            out.frames.push_back(detail::to_rgb(frame.get()));
            out.seconds.push_back(double(frame->best_effort_timestamp) * av_q2d(stream->time_base));
        }
    };
    while (av_read_frame(format.get(), packet.get()) >= 0) {
        if (packet->stream_index == index) avcodec_send_packet(codec.get(), packet.get());
        av_packet_unref(packet.get());
        receive();
    }
    avcodec_send_packet(codec.get(), nullptr);
    receive();
    return out;
}

} // namespace tumble::test
