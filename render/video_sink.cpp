#include "render/video_sink.h"
#include "render/libav_owners.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <array>
#include <cctype>

namespace tumble::render {

namespace fs = std::filesystem;

namespace {

std::string av_error_text(int code) {
    return libav::error_text(code);
}

// Owning pointers for the libav objects (render/libav_owners.h), and swscale's.
using libav::CodecFree;
using libav::FormatFree;
using libav::FrameFree;
using libav::PacketFree;
struct ScalerFree {
    void operator()(SwsContext* s) const { sws_freeContext(s); }
};

constexpr std::array<const char*, 10> kPresets = {"ultrafast", "superfast", "veryfast", "faster",
                                                  "fast",      "medium",    "slow",     "slower",
                                                  "veryslow",  "placebo"};

// The two kinds of video file (see video_sink.h).
struct Format {
    const char* muxer;   // libavformat's name
    const char* encoder; // libavcodec's name
    int max_crf;
    bool vp9;
};

Format format_of(const fs::path& output) {
    std::string ext = output.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".webm") return {"webm", "libvpx-vp9", 63, true};
    return {"mp4", "libx264", 51, false};
}

// Everything that can be checked before touching the disk, so a bad request leaves no trace.
void check_options(const std::string& output, const SinkOptions& o, const Format& format) {
    const auto fail = [&](const std::string& why) {
        throw SinkError("cannot write '" + output + "': " + why);
    };
    const std::string size = std::to_string(o.width) + "x" + std::to_string(o.height);
    if (o.width <= 0 || o.height <= 0) fail("video needs a frame size, got " + size);
    if (o.width % 2 != 0 || o.height % 2 != 0) {
        fail(std::string(format.vp9 ? "VP9" : "H.264") +
             " yuv420p needs even width and height, got " + size +
             " (chroma is stored at half resolution); use e.g. " +
             std::to_string(o.width + o.width % 2) + "x" + std::to_string(o.height + o.height % 2));
    }
    if (o.fps <= 0) fail("fps must be positive, got " + std::to_string(o.fps));
    if (o.crf < 0 || o.crf > format.max_crf)
        fail("crf must be 0.." + std::to_string(format.max_crf) + ", got " + std::to_string(o.crf));
    if (o.threads < 0) fail("threads must be >= 0, got " + std::to_string(o.threads));
    if (std::find(kPresets.begin(), kPresets.end(), o.preset) == kPresets.end()) {
        std::string known;
        for (const char* p : kPresets) known += std::string(known.empty() ? "" : ", ") + p;
        fail("unknown preset '" + o.preset + "' (known: " + known + ")");
    }
}

} // namespace

struct VideoSink::Encoder {
    std::unique_ptr<AVFormatContext, FormatFree> format;
    std::unique_ptr<AVCodecContext, CodecFree> codec;
    std::unique_ptr<SwsContext, ScalerFree> scaler;
    std::unique_ptr<AVFrame, FrameFree> frame; // the yuv420p picture handed to the encoder
    std::unique_ptr<AVPacket, PacketFree> packet;
    AVStream* stream = nullptr; // owned by `format`
    std::string output;         // for messages
    std::string comment;        // the container's comment tag (SinkOptions::comment)
    Format kind;

    void check(int code, const char* what) const {
        if (code < 0) {
            throw SinkError("cannot write '" + output + "': " + what + ": " + av_error_text(code));
        }
    }
    void open_codec(const SinkOptions& o);
    void restart_codec(const SinkOptions& o);
    void open_container(const fs::path& temp, bool stream_out);
    void open_scaler(const SinkOptions& o);
    void encode(const AVFrame* frame); // nullptr drains the encoder
};

// libvpx's settings for a preset name: its speed/quality trade-off, and a constant quality.
std::string vp9_settings(const SinkOptions& o, AVDictionary** settings) {
    const auto at = std::find(kPresets.begin(), kPresets.end(), o.preset) - kPresets.begin();
    const bool realtime = at <= 3; // ultrafast .. faster
    const int cpu_used = realtime ? 8 : at <= 5 ? 4 : 2;
    av_dict_set(settings, "deadline", realtime ? "realtime" : "good", 0);
    av_dict_set_int(settings, "cpu-used", cpu_used, 0);
    av_dict_set_int(settings, "crf", o.crf, 0);
    av_dict_set(settings, "b", "0", 0); // quality-driven, no bitrate target
    return std::string(realtime ? "realtime" : "good") + ", cpu-used " + std::to_string(cpu_used) +
           ", crf " + std::to_string(o.crf);
}

void VideoSink::Encoder::open_codec(const SinkOptions& o) {
    const AVCodec* x264 = avcodec_find_encoder_by_name(kind.encoder);
    if (!x264)
        throw SinkError("cannot write '" + output + "': this FFmpeg has no " +
                        std::string(kind.encoder) + " encoder");
    codec.reset(avcodec_alloc_context3(x264));
    if (!codec) throw SinkError("cannot write '" + output + "': out of memory");
    AVCodecContext* c = codec.get();
    c->width = o.width;
    c->height = o.height;
    c->pix_fmt = AV_PIX_FMT_YUV420P;
    c->time_base = AVRational{1, o.fps}; // one tick per frame: pts = frame index
    c->framerate = AVRational{o.fps, 1};
    c->sample_aspect_ratio = AVRational{1, 1};
    // Say how the YUV was made (see open_scaler): the tags go into the H.264 VUI and the MP4.
    c->color_range = AVCOL_RANGE_MPEG;
    c->colorspace = AVCOL_SPC_BT709;
    c->color_primaries = AVCOL_PRI_BT709;
    c->color_trc = AVCOL_TRC_BT709;
    c->thread_count = o.threads; // libx264's own default is 0 = per core; see SinkOptions
    c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER; // MP4 keeps SPS/PPS in the header (avcC)
    AVDictionary* settings = nullptr;
    if (kind.vp9) {
        const std::string what = "opening libvpx-vp9 (" + vp9_settings(o, &settings) + ")";
        const int opened = avcodec_open2(c, x264, &settings);
        av_dict_free(&settings);
        check(opened, what.c_str());
        return;
    }
    av_dict_set(&settings, "preset", o.preset.c_str(), 0);
    av_dict_set_int(&settings, "crf", o.crf, 0);
    // Same algorithms whatever SIMD the CPU has, so the bytes do not depend on the machine.
    const std::string params =
        "cpu-independent=1" + (o.x264_params.empty() ? "" : ":" + o.x264_params);
    av_dict_set(&settings, "x264-params", params.c_str(), 0);
    const int opened = avcodec_open2(c, x264, &settings);
    av_dict_free(&settings);
    const std::string what = "opening libx264 (preset " + o.preset + ", crf " +
                             std::to_string(o.crf) + ", x264-params " + params + ")";
    check(opened, what.c_str());
}

// A key frame of SinkOptions::key_interval: drains x264 and opens a fresh one with the same
// settings, whose first frame is an IDR picture. The stream keeps the first encoder's SPS and PPS
// (the MP4's avcC); a fresh x264 with the same settings makes the same ones, and if it ever did
// not, the file would decode wrongly after this point, so that is checked rather than assumed.
void VideoSink::Encoder::restart_codec(const SinkOptions& o) {
    encode(nullptr);
    open_codec(o);
    const AVCodecParameters* p = stream->codecpar;
    const bool same =
        codec->extradata_size == p->extradata_size &&
        std::equal(codec->extradata, codec->extradata + p->extradata_size, p->extradata);
    if (!same)
        throw SinkError("cannot write '" + output +
                        "': the restarted encoder made other stream headers (SPS/PPS) than the "
                        "first; the key-frame segments cannot share one stream");
}

void VideoSink::Encoder::open_container(const fs::path& temp, bool stream_out) {
    // "file:" stops libavformat from reading a colon in the name as a protocol ("a:b.mp4"), and
    // the muxer is named because the temporary name does not end in .mp4. A pipe is written
    // through the same protocol; it only cannot seek (see the movflags below).
    const std::string url = "file:" + temp.string();
    AVFormatContext* f = nullptr;
    check(avformat_alloc_output_context2(&f, nullptr, kind.muxer, url.c_str()),
          "creating the muxer");
    format.reset(f);
    // Matroska writes a random segment UID and the muxing date unless asked to be bit-exact.
    if (kind.vp9) f->flags |= AVFMT_FLAG_BITEXACT;
    stream = avformat_new_stream(f, nullptr);
    if (!stream) throw SinkError("cannot write '" + output + "': out of memory");
    check(avcodec_parameters_from_context(stream->codecpar, codec.get()), "stream parameters");
    // A wish: the MP4 muxer raises the timescale to at least 10000 by doubling (1/30 becomes
    // 1/15360, 512 ticks per frame), which keeps every timestamp an exact integer.
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = codec->framerate;
    check(avio_open(&f->pb, url.c_str(), AVIO_FLAG_WRITE), "creating the file");
    if (!comment.empty()) av_dict_set(&f->metadata, "comment", comment.c_str(), 0);
    AVDictionary* settings = nullptr;
    // faststart: at the end, rewrite the file with the index ("moov") first. That second pass
    // reopens the file by its name, which is why the name is set above. A pipe (a FIFO, standard
    // output) cannot be rewritten or seeked, so it gets fragmented MP4 instead: an empty index
    // first, then self-contained fragments, one per keyframe; players read it as it arrives.
    if (!kind.vp9)
        av_dict_set(&settings, "movflags",
                    stream_out ? "+frag_keyframe+empty_moov+default_base_moof" : "+faststart", 0);
    const int written = avformat_write_header(f, &settings);
    av_dict_free(&settings);
    check(written, "writing the file header");
}

// RGB -> YUV with the BT.709 matrix, from full-range RGB (0..255) to limited-range YUV (Y 16..235,
// U/V 16..240), matching the tags set in open_codec. SWS_ACCURATE_RND avoids the fast paths'
// rounding bias. SWS_BITEXACT asks for the same result from every SIMD code path: measured, the
// output already matched with SIMD switched off, but the flag makes that a promise rather than
// luck, which the determinism guarantee needs.
void VideoSink::Encoder::open_scaler(const SinkOptions& o) {
    scaler.reset(sws_getContext(o.width, o.height, AV_PIX_FMT_RGB24, o.width, o.height,
                                AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_BITEXACT,
                                nullptr, nullptr, nullptr));
    if (!scaler) throw SinkError("cannot write '" + output + "': no RGB -> yuv420p converter");
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    constexpr int full_range = 1, limited_range = 0, brightness = 0, unit = 1 << 16;
    sws_setColorspaceDetails(scaler.get(), bt709, full_range, bt709, limited_range, brightness,
                             unit, unit);
    frame.reset(av_frame_alloc());
    packet.reset(av_packet_alloc());
    if (!frame || !packet) throw SinkError("cannot write '" + output + "': out of memory");
    frame->format = AV_PIX_FMT_YUV420P;
    frame->width = o.width;
    frame->height = o.height;
    check(av_frame_get_buffer(frame.get(), 0), "allocating a frame");
}

void VideoSink::Encoder::encode(const AVFrame* picture) {
    check(avcodec_send_frame(codec.get(), picture), "encoding");
    for (;;) {
        const int got = avcodec_receive_packet(codec.get(), packet.get());
        if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return; // needs more input / drained
        check(got, "encoding");
        // Constant frame rate: every frame lasts one tick. Setting it explicitly gives the last
        // frame its duration too, so the container's duration is exactly frames / fps.
        if (packet->duration == 0) packet->duration = 1;
        av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
        packet->stream_index = stream->index;
        check(av_interleaved_write_frame(format.get(), packet.get()), "writing a packet");
    }
}

VideoSink::VideoSink(const fs::path& output, const SinkOptions& options)
    : file_(output), options_(options) {
    const Format kind = format_of(output);
    check_options(output.string(), options, kind);
    try {
        if (!file_.streaming()) io::ensure_writable_directory(output.parent_path());
    } catch (const io::FileError& e) {
        throw SinkError("cannot write '" + output.string() + "': " + e.what());
    }
    encoder_ = std::make_unique<Encoder>();
    encoder_->output = output.string();
    encoder_->comment = options.comment;
    encoder_->kind = kind;
    try {
        encoder_->open_codec(options);
        encoder_->open_container(file_.temp_path(), file_.streaming());
        encoder_->open_scaler(options);
    } catch (...) {
        abort();
        throw;
    }
}

VideoSink::~VideoSink() {
    abort();
}

void VideoSink::write(const Image& image) {
    detail::check_open(*this, done_);
    detail::check_frame(describe(), image, options_.width, options_.height);
    AVFrame* frame = encoder_->frame.get();
    // The encoder may still hold the previous picture (lookahead): get a buffer of our own.
    encoder_->check(av_frame_make_writable(frame), "allocating a frame");
    const std::uint8_t* source[1] = {image.rgb.data()};
    const int source_stride[1] = {image.width * 3};
    sws_scale(encoder_->scaler.get(), source, source_stride, 0, image.height, frame->data,
              frame->linesize);
    const std::int64_t k = options_.first_frame + frames_; // the frame's index in the whole run
    if (!encoder_->kind.vp9 && options_.key_interval > 0 && frames_ > 0 &&
        k % options_.key_interval == 0)
        encoder_->restart_codec(options_);
    frame->pts = frames_;
    encoder_->encode(frame);
    ++frames_;
}

void VideoSink::finish() {
    detail::finish_sink(*this, done_, frames_, [&] {
        encoder_->encode(nullptr); // flush the frames x264 still holds (lookahead, B-frames)
        encoder_->check(av_write_trailer(encoder_->format.get()), "finishing the file");
        encoder_->check(avio_closep(&encoder_->format->pb), "closing the file");
        encoder_.reset();
        file_.commit();
    });
}

void quiet_video_logs() {
    av_log_set_level(AV_LOG_WARNING);
}

void VideoSink::abort() noexcept {
    if (done_) return;
    encoder_.reset(); // closes the file before it is deleted
    file_.discard();
    done_ = true;
}

} // namespace tumble::render
