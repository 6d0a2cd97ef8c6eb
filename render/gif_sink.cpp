#include "render/gif_sink.h"
#include "render/libav_owners.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
}

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace tumble::render {
namespace {

namespace fs = std::filesystem;

struct GraphFree {
    void operator()(AVFilterGraph* g) const { avfilter_graph_free(&g); }
};
using Graph = std::unique_ptr<AVFilterGraph, GraphFree>;
using libav::Frame;

std::string av_message(int code) {
    return libav::error_text(code);
}

// A filter graph from its description, with named sources (buffer) and one sink (buffersink).
struct Pipeline {
    Graph graph{avfilter_graph_alloc()};
    std::vector<AVFilterContext*> sources;
    AVFilterContext* sink = nullptr;
};

AVFilterContext* add_source(Pipeline& p, const char* name, int w, int h, AVPixelFormat format,
                            int fps, const std::string& output) {
    char args[200];
    std::snprintf(args, sizeof args, "video_size=%dx%d:pix_fmt=%d:time_base=1/%d:pixel_aspect=1/1",
                  w, h, int(format), fps);
    AVFilterContext* src = nullptr;
    const int r = avfilter_graph_create_filter(&src, avfilter_get_by_name("buffer"), name, args,
                                               nullptr, p.graph.get());
    if (r < 0) throw SinkError("cannot write '" + output + "': buffer: " + av_message(r));
    p.sources.push_back(src);
    return src;
}

// Links sources (labelled in0, in1, ...) through `description` into a buffersink.
void link(Pipeline& p, const std::string& description, const std::string& output) {
    const int r0 = avfilter_graph_create_filter(&p.sink, avfilter_get_by_name("buffersink"), "out",
                                                nullptr, nullptr, p.graph.get());
    if (r0 < 0) throw SinkError("cannot write '" + output + "': buffersink: " + av_message(r0));
    AVFilterInOut* outputs = nullptr;
    for (std::size_t i = p.sources.size(); i-- > 0;) {
        AVFilterInOut* io = avfilter_inout_alloc();
        io->name = av_strdup(("in" + std::to_string(i)).c_str());
        io->filter_ctx = p.sources[i];
        io->pad_idx = 0;
        io->next = outputs;
        outputs = io;
    }
    AVFilterInOut* inputs = avfilter_inout_alloc();
    inputs->name = av_strdup("out");
    inputs->filter_ctx = p.sink;
    inputs->pad_idx = 0;
    inputs->next = nullptr;
    int r =
        avfilter_graph_parse_ptr(p.graph.get(), description.c_str(), &inputs, &outputs, nullptr);
    avfilter_inout_free(&inputs);
    avfilter_inout_free(&outputs);
    if (r >= 0) r = avfilter_graph_config(p.graph.get(), nullptr);
    if (r < 0)
        throw SinkError("cannot write '" + output + "': filter graph '" + description +
                        "': " + av_message(r));
}

} // namespace

GifSink::GifSink(const fs::path& output, const SinkOptions& options)
    : file_(output), options_(options) {
    if (file_.streaming())
        throw SinkError("cannot write '" + output.string() +
                        "': a GIF is made after its last frame (one palette for the whole video), "
                        "so it needs a regular file, not a stream");
    if (options.width <= 0 || options.height <= 0 || options.fps <= 0)
        throw SinkError("cannot write '" + output.string() +
                        "': the GIF needs a frame size and fps");
    try {
        io::ensure_writable_directory(output.parent_path());
    } catch (const io::FileError& e) {
        throw SinkError("cannot write '" + output.string() + "': " + e.what());
    }
    stride_ = static_cast<int>(std::ceil(options.fps / 50.0));
    spool_path_ = file_.temp_path().string() + ".frames";
    spool_ = std::fopen(spool_path_.c_str(), "wb");
    if (!spool_) throw SinkError("cannot write '" + spool_path_.string() + "'");
}

GifSink::~GifSink() {
    abort();
}

std::string GifSink::note() const {
    if (stride_ == 1) return "";
    const int fps = options_.fps;
    return describe() + " plays at " + std::to_string(fps / stride_) + " fps, every " +
           std::to_string(stride_) +
           (stride_ == 2   ? "nd"
            : stride_ == 3 ? "rd"
                           : "th") +
           " frame of " + std::to_string(fps) +
           " fps (GIF frame delays are whole centiseconds, and browsers slow down those under "
           "2 cs); --fps 50 or less keeps every frame";
}

void GifSink::write(const Image& image) {
    detail::check_open(*this, done_);
    if (image.width != options_.width || image.height != options_.height)
        throw SinkError("'" + describe() + "': frame of " + std::to_string(image.width) + "x" +
                        std::to_string(image.height) + ", expected " +
                        std::to_string(options_.width) + "x" + std::to_string(options_.height));
    if (frames_++ % stride_ != 0) return; // above 50 fps: every stride-th frame
    if (std::fwrite(image.rgb.data(), 1, image.rgb.size(), spool_) != image.rgb.size())
        throw SinkError("cannot write '" + spool_path_.string() + "' (disk full?)");
    ++kept_;
}

void GifSink::finish() {
    detail::finish_sink(*this, done_, frames_, [&] {
        const int closed = std::fclose(spool_);
        spool_ = nullptr;
        if (closed != 0) throw SinkError("cannot write '" + spool_path_.string() + "'");
        encode();
        file_.commit();
        std::error_code ec;
        fs::remove(spool_path_, ec);
    });
}

void GifSink::abort() noexcept {
    if (spool_) std::fclose(spool_), spool_ = nullptr;
    std::error_code ec;
    if (!spool_path_.empty()) fs::remove(spool_path_, ec);
    file_.discard();
    done_ = true;
}

void GifSink::encode() {
    const int w = options_.width, h = options_.height, fps = options_.fps / stride_;
    const std::string out = describe();
    const std::size_t bytes = std::size_t(w) * h * 3;
    auto read_frames = [&](auto&& each) {
        std::FILE* in = std::fopen(spool_path_.c_str(), "rb");
        if (!in) throw SinkError("cannot read '" + spool_path_.string() + "'");
        std::unique_ptr<std::FILE, int (*)(std::FILE*)> closer(in, std::fclose);
        for (std::int64_t k = 0; k < kept_; ++k) {
            Frame f(av_frame_alloc());
            f->width = w, f->height = h, f->format = AV_PIX_FMT_RGB24, f->pts = k;
            if (av_frame_get_buffer(f.get(), 0) < 0) throw SinkError("out of memory");
            std::vector<std::uint8_t> rgb(bytes);
            if (std::fread(rgb.data(), 1, bytes, in) != bytes)
                throw SinkError("cannot read '" + spool_path_.string() + "'");
            for (int y = 0; y < h; ++y)
                std::memcpy(f->data[0] + std::size_t(y) * f->linesize[0],
                            rgb.data() + std::size_t(y) * w * 3, std::size_t(w) * 3);
            each(std::move(f));
        }
    };
    auto check = [&](int r, const char* what) {
        if (r < 0) throw SinkError("cannot write '" + out + "': " + what + ": " + av_message(r));
    };

    // 1. The palette of the whole video. palettegen reports at warning level every colour it
    // merged ("Duped color") when a video has fewer than 256: nothing for the user to act on, so
    // the log is held at errors while the GIF is made (the level is process-wide; restored after).
    struct QuietPalette {
        int level = av_log_get_level();
        QuietPalette() { av_log_set_level(std::min(level, AV_LOG_ERROR)); }
        ~QuietPalette() { av_log_set_level(level); }
    } quiet;
    Pipeline first;
    add_source(first, "in0", w, h, AV_PIX_FMT_RGB24, fps, out);
    link(first, "[in0]palettegen=stats_mode=full[out]", out);
    read_frames(
        [&](Frame f) { check(av_buffersrc_add_frame(first.sources[0], f.get()), "palettegen"); });
    check(av_buffersrc_add_frame(first.sources[0], nullptr), "palettegen");
    Frame palette(av_frame_alloc());
    check(av_buffersink_get_frame(first.sink, palette.get()), "palettegen");

    // 2. Every frame onto it, encoded and muxed.
    Pipeline second;
    add_source(second, "in0", w, h, AV_PIX_FMT_RGB24, fps, out);
    add_source(second, "in1", palette->width, palette->height, AVPixelFormat(palette->format), fps,
               out);
    link(second, "[in0][in1]paletteuse=dither=sierra2_4a[out]", out);
    palette->pts = 0;
    check(av_buffersrc_add_frame(second.sources[1], palette.get()), "paletteuse");
    check(av_buffersrc_add_frame(second.sources[1], nullptr), "paletteuse");

    const AVCodec* gif = avcodec_find_encoder(AV_CODEC_ID_GIF);
    if (!gif) throw SinkError("cannot write '" + out + "': this FFmpeg has no GIF encoder");
    libav::Codec codec(avcodec_alloc_context3(gif));
    codec->width = w, codec->height = h, codec->pix_fmt = AV_PIX_FMT_PAL8;
    codec->time_base = AVRational{1, fps};
    codec->flags |= AV_CODEC_FLAG_BITEXACT;
    check(avcodec_open2(codec.get(), gif, nullptr), "opening the GIF encoder");
    const std::string url = "file:" + file_.temp_path().string();
    AVFormatContext* fmt = nullptr;
    check(avformat_alloc_output_context2(&fmt, nullptr, "gif", url.c_str()), "GIF muxer");
    libav::Format format(fmt);
    AVStream* stream = avformat_new_stream(fmt, nullptr);
    if (!stream) throw SinkError("cannot write '" + out + "': out of memory");
    check(avcodec_parameters_from_context(stream->codecpar, codec.get()), "stream parameters");
    stream->time_base = codec->time_base;
    check(avio_open(&fmt->pb, url.c_str(), AVIO_FLAG_WRITE), "creating the file");
    check(avformat_write_header(fmt, nullptr), "writing the GIF header");
    libav::Packet packet_owner(av_packet_alloc());
    AVPacket* packet = packet_owner.get();
    auto drain = [&] {
        while (avcodec_receive_packet(codec.get(), packet) == 0) {
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            check(av_interleaved_write_frame(fmt, packet), "writing a frame");
        }
    };
    auto pull = [&] {
        for (;;) {
            Frame mapped(av_frame_alloc());
            const int r = av_buffersink_get_frame(second.sink, mapped.get());
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            check(r, "paletteuse");
            check(avcodec_send_frame(codec.get(), mapped.get()), "encoding a frame");
            drain();
        }
    };
    read_frames([&](Frame f) {
        check(av_buffersrc_add_frame(second.sources[0], f.get()), "paletteuse");
        pull();
    });
    check(av_buffersrc_add_frame(second.sources[0], nullptr), "paletteuse");
    pull();
    check(avcodec_send_frame(codec.get(), nullptr), "finishing the encoder");
    drain();
    check(av_write_trailer(fmt), "finishing the file");
}

} // namespace tumble::render
