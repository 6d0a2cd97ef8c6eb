// The video sinks (MP4 and WebM), checked by decoding its files with libavformat/libavcodec (what a
// player sees) and by what it leaves on disk after finish(), abort() and errors.
#include "render/open_sink.h"
#include "render/video_sink.h"

#include "test_support.h"

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/cpu.h>
#include <libavutil/pixdesc.h>
}

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>

namespace tumble::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_artifact_dir;
using test::list_dir;

// libx264 and the MP4 muxer log statistics at "info" level; keep the test output readable.
class QuietVideoLogs : public ::testing::Environment {
    void SetUp() override { quiet_video_logs(); }
};
const auto* const quiet_logs = ::testing::AddGlobalTestEnvironment(new QuietVideoLogs);

// ---- reading an MP4 back -----------------------------------------------------------------------

struct VideoFacts {
    std::string codec, pix_fmt;
    int width = 0, height = 0;
    AVRational avg_frame_rate{0, 1}, r_frame_rate{0, 1};
    double stream_seconds = 0, container_seconds = 0;
    int decoded_frames = 0;
    AVColorRange range = AVCOL_RANGE_UNSPECIFIED;
    AVColorSpace space = AVCOL_SPC_UNSPECIFIED;
    int first_y = -1, first_u = -1, first_v = -1; // centre pixel of the first decoded frame
};

VideoFacts probe(const fs::path& path) {
    VideoFacts facts;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
        ADD_FAILURE() << "libavformat cannot open " << path;
        return facts;
    }
    std::unique_ptr<AVFormatContext, void (*)(AVFormatContext*)> format_owner(
        format, [](AVFormatContext* f) { avformat_close_input(&f); });
    EXPECT_GE(avformat_find_stream_info(format, nullptr), 0);
    const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) {
        ADD_FAILURE() << "no video stream in " << path;
        return facts;
    }
    const AVStream* stream = format->streams[index];
    const AVCodecParameters* par = stream->codecpar;
    facts.codec = avcodec_get_name(par->codec_id);
    const char* pix = av_get_pix_fmt_name(static_cast<AVPixelFormat>(par->format));
    facts.pix_fmt = pix ? pix : "?";
    facts.width = par->width, facts.height = par->height;
    facts.avg_frame_rate = stream->avg_frame_rate, facts.r_frame_rate = stream->r_frame_rate;
    facts.stream_seconds = static_cast<double>(stream->duration) * av_q2d(stream->time_base);
    facts.container_seconds = static_cast<double>(format->duration) / AV_TIME_BASE;
    facts.range = par->color_range, facts.space = par->color_space;

    // Decode everything: the count of pictures a player would show.
    const AVCodec* decoder = avcodec_find_decoder(par->codec_id);
    std::unique_ptr<AVCodecContext, void (*)(AVCodecContext*)> codec(
        avcodec_alloc_context3(decoder), [](AVCodecContext* c) { avcodec_free_context(&c); });
    avcodec_parameters_to_context(codec.get(), par);
    EXPECT_GE(avcodec_open2(codec.get(), decoder, nullptr), 0);
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    const auto drain = [&] {
        while (avcodec_receive_frame(codec.get(), frame) >= 0) {
            if (facts.decoded_frames++ == 0) {
                const int x = frame->width / 2, y = frame->height / 2;
                facts.first_y = frame->data[0][y * frame->linesize[0] + x];
                facts.first_u = frame->data[1][y / 2 * frame->linesize[1] + x / 2];
                facts.first_v = frame->data[2][y / 2 * frame->linesize[2] + x / 2];
            }
        }
    };
    while (av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == index) {
            avcodec_send_packet(codec.get(), packet);
            drain();
        }
        av_packet_unref(packet);
    }
    avcodec_send_packet(codec.get(), nullptr);
    drain();
    av_frame_free(&frame);
    av_packet_free(&packet);
    return facts;
}

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

// Top-level MP4 box types in file order ("ftyp", "moov", "mdat" ...).
std::vector<std::string> top_level_boxes(const fs::path& path) {
    const std::string bytes = read_bytes(path);
    std::vector<std::string> boxes;
    for (std::size_t at = 0; at + 8 <= bytes.size();) {
        const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(bytes[at + i]); };
        std::uint64_t size =
            (std::uint64_t{byte(0)} << 24) | (byte(1) << 16) | (byte(2) << 8) | byte(3);
        boxes.push_back(bytes.substr(at + 4, 4));
        if (size == 1 && at + 16 <= bytes.size()) { // 64-bit size follows the type
            size = 0;
            for (int i = 8; i < 16; ++i) size = (size << 8) | byte(i);
        }
        if (size < 8) break;
        at += size;
    }
    return boxes;
}

// 30 frames of moving content: the balls slide right by two pixels per frame.
void write_moving_frames(FrameSink& sink, int width, int height, int count = 30) {
    for (int k = 0; k < count; ++k) sink.write(test::rendered_like(width, height, 2.0 * k));
}

SinkOptions video_options(int width = 64, int height = 48, int fps = 30) {
    SinkOptions options;
    options.width = width, options.height = height, options.fps = fps;
    return options;
}

// ---- MP4 ---------------------------------------------------------------------------------------

TEST(Mp4Sink, PlaysWithExactFrameRateDurationAndFormat) {
    const fs::path dir = fresh_artifact_dir();
    const fs::path path = dir / "moving.mp4";
    auto sink = open_sink(path.string(), video_options());
    write_moving_frames(*sink, 64, 48);
    EXPECT_EQ(sink->frames_written(), 30);
    sink->finish();
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"moving.mp4"}); // no temporary left

    const VideoFacts v = probe(path);
    EXPECT_EQ(v.codec, "h264");
    EXPECT_EQ(v.pix_fmt, "yuv420p");
    EXPECT_EQ(v.width, 64);
    EXPECT_EQ(v.height, 48);
    EXPECT_EQ(v.decoded_frames, 30);
    EXPECT_EQ(av_cmp_q(v.avg_frame_rate, AVRational{30, 1}), 0)
        << v.avg_frame_rate.num << "/" << v.avg_frame_rate.den;
    EXPECT_EQ(av_cmp_q(v.r_frame_rate, AVRational{30, 1}), 0)
        << v.r_frame_rate.num << "/" << v.r_frame_rate.den;
    EXPECT_NEAR(v.stream_seconds, 1.0, 1.0 / 30);
    EXPECT_NEAR(v.container_seconds, 1.0, 1.0 / 30);
    EXPECT_EQ(v.range, AVCOL_RANGE_MPEG);
    EXPECT_EQ(v.space, AVCOL_SPC_BT709);
}

TEST(Mp4Sink, IndexComesFirstForBrowsers) {
    const fs::path path = fresh_artifact_dir() / "faststart.mp4";
    auto sink = open_sink(path.string(), video_options());
    write_moving_frames(*sink, 64, 48, 5);
    sink->finish();
    const std::vector<std::string> boxes = top_level_boxes(path);
    const auto at = [&](const char* type) { return std::find(boxes.begin(), boxes.end(), type); };
    ASSERT_NE(at("moov"), boxes.end());
    ASSERT_NE(at("mdat"), boxes.end());
    EXPECT_LT(at("moov"), at("mdat")) << "movflags=+faststart should put moov before mdat";
}

// Pure red through BT.709 limited range: Y = 16 + 219 * 0.2126 = 62.6, Cb = 128 - 224 * 0.1146
// = 102.3, Cr = 240. BT.601 would give Y = 81.5, Cb = 90.2; full range would give Y = 54.
TEST(Mp4Sink, ConvertsWithBt709LimitedRange) {
    const fs::path path = fresh_artifact_dir() / "red.mp4";
    auto sink = open_sink(path.string(), video_options(32, 32));
    Image red(32, 32);
    for (std::size_t i = 0; i < red.rgb.size(); i += 3) red.rgb[i] = 255;
    for (int k = 0; k < 3; ++k) sink->write(red);
    sink->finish();
    const VideoFacts v = probe(path);
    EXPECT_NEAR(v.first_y, 63, 2);
    EXPECT_NEAR(v.first_u, 102, 2);
    EXPECT_NEAR(v.first_v, 240, 2);
}

TEST(Mp4Sink, SameFramesGiveSameBytes) {
    const fs::path dir = fresh_artifact_dir();
    for (const char* name : {"a.mp4", "b.mp4"}) {
        auto sink = open_sink((dir / name).string(), video_options());
        write_moving_frames(*sink, 64, 48);
        sink->finish();
    }
    EXPECT_TRUE(read_bytes(dir / "a.mp4") == read_bytes(dir / "b.mp4"));
}

// The bytes must not depend on the CPU: encode once normally and once with every SIMD path
// switched off (libav's, which swscale uses, and x264's own via asm=0). They match only because
// the sink asks for SWS_BITEXACT and x264's cpu-independent=1.
TEST(Mp4Sink, SameBytesWithoutSimd) {
    const fs::path dir = fresh_artifact_dir();
    const auto encode = [&](const char* name, const std::string& x264_params) {
        SinkOptions options = video_options();
        options.x264_params = x264_params;
        auto sink = open_sink((dir / name).string(), options);
        write_moving_frames(*sink, 64, 48);
        sink->finish();
    };
    encode("simd.mp4", "");
    av_force_cpu_flags(0); // process-wide: restored below
    encode("plain_c.mp4", "asm=0");
    av_force_cpu_flags(-1);
    EXPECT_TRUE(read_bytes(dir / "simd.mp4") == read_bytes(dir / "plain_c.mp4"));
}

TEST(Mp4Sink, OddDimensionsAreRefusedWithoutLeavingAFile) {
    const fs::path dir = fresh_artifact_dir();
    for (const auto& [w, h] : {std::pair{63, 48}, std::pair{64, 47}}) {
        try {
            open_sink((dir / "odd.mp4").string(), video_options(w, h));
            ADD_FAILURE() << "odd size " << w << "x" << h << " accepted";
        } catch (const SinkError& e) {
            EXPECT_NE(std::string(e.what()).find("even"), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(list_dir(dir).empty());
}

TEST(Mp4Sink, AbortLeavesNothing) {
    const fs::path dir = fresh_artifact_dir();
    auto sink = open_sink((dir / "aborted.mp4").string(), video_options());
    write_moving_frames(*sink, 64, 48, 10);
    EXPECT_EQ(list_dir(dir).size(), 1u); // the temporary file, while encoding
    sink->abort();
    EXPECT_TRUE(list_dir(dir).empty());
}

// A full disk (simulated with a file size limit) during encoding or in finish() gives a SinkError
// naming the file, and nothing is left behind.
TEST(Mp4Sink, FullDiskFailsCleanly) {
    const fs::path dir = fresh_artifact_dir();
    SinkOptions lossless = video_options(256, 256);
    lossless.crf = 0; // noise at crf 0: far more than the limit
    auto sink = open_sink((dir / "full.mp4").string(), lossless);
    const test::FileSizeLimit limit(64 * 1024);
    try {
        for (int k = 0; k < 10; ++k) sink->write(test::noise(256, 256, k));
        sink->finish();
        ADD_FAILURE() << "no error although the file could not grow";
    } catch (const SinkError& e) {
        EXPECT_NE(std::string(e.what()).find("full.mp4"), std::string::npos) << e.what();
        sink->abort();
    }
    EXPECT_TRUE(list_dir(dir).empty());
}

TEST(Mp4Sink, DestructorWithoutFinishLeavesNothing) {
    const fs::path dir = fresh_artifact_dir();
    {
        auto sink = open_sink((dir / "dropped.mp4").string(), video_options());
        write_moving_frames(*sink, 64, 48, 10);
    }
    EXPECT_TRUE(list_dir(dir).empty());
}

// The app stops early on Ctrl-C and calls finish(): the frames so far must make a valid video.
TEST(Mp4Sink, FinishAfterAnyFrameCountPlays) {
    const fs::path dir = fresh_artifact_dir();
    for (int frames : {1, 7}) {
        const fs::path path = dir / ("short" + std::to_string(frames) + ".mp4");
        auto sink = open_sink(path.string(), video_options());
        write_moving_frames(*sink, 64, 48, frames);
        sink->finish();
        const VideoFacts v = probe(path);
        EXPECT_EQ(v.decoded_frames, frames);
        EXPECT_NEAR(v.stream_seconds, frames / 30.0, 1.0 / 30);
    }
    EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"short1.mp4", "short7.mp4"}));
}

// libavformat reads a relative "take:2.mp4" as protocol "take" unless told it is a file.
TEST(Mp4Sink, ColonInTheNameIsJustAFileName) {
    const fs::path dir = fresh_artifact_dir();
    const fs::path previous = fs::current_path();
    fs::current_path(dir); // a relative name, as a user would type it
    try {
        auto sink = open_sink("take:2.mp4", video_options());
        write_moving_frames(*sink, 64, 48, 3);
        sink->finish();
    } catch (const SinkError& e) {
        ADD_FAILURE() << e.what();
    }
    fs::current_path(previous);
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"take:2.mp4"});
    EXPECT_EQ(probe(dir / "take:2.mp4").decoded_frames, 3);
}

TEST(Mp4Sink, RefusesWrongFrameSizeAndEmptyFinish) {
    const fs::path dir = fresh_artifact_dir();
    auto sink = open_sink((dir / "x.mp4").string(), video_options());
    EXPECT_THROW(sink->write(test::rendered_like(32, 24)), SinkError);
    EXPECT_THROW(sink->finish(), SinkError); // no frames: nothing to save
    EXPECT_TRUE(list_dir(dir).empty());
}

TEST(Mp4Sink, RejectsBadOptionsClearly) {
    const fs::path path = fresh_artifact_dir() / "x.mp4";
    SinkOptions bad_preset = video_options();
    bad_preset.preset = "warpspeed";
    EXPECT_THROW(open_sink(path.string(), bad_preset), SinkError);
    SinkOptions bad_crf = video_options();
    bad_crf.crf = 60;
    EXPECT_THROW(open_sink(path.string(), bad_crf), SinkError);
    bad_crf.crf = 64; // VP9's scale ends at 63
    EXPECT_THROW(open_sink((path.parent_path() / "bad.webm").string(), bad_crf), SinkError);
    EXPECT_THROW(open_sink(path.string(), video_options(0, 0)), SinkError);
    EXPECT_TRUE(list_dir(path.parent_path()).empty());
}

// Optional cross-check with the ffprobe command line tool, when it is installed.
TEST(Mp4Sink, FfprobeAgrees) {
    if (std::system("ffprobe -version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no ffprobe";
    const fs::path path = fresh_artifact_dir() / "probe.mp4";
    auto sink = open_sink(path.string(), video_options());
    write_moving_frames(*sink, 64, 48);
    sink->finish();
    const std::string command = "ffprobe -v error -count_frames -select_streams v:0 "
                                "-show_entries stream=codec_name,pix_fmt,nb_read_frames,"
                                "avg_frame_rate,duration -of default=nw=1 '" +
                                path.string() + "'";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    ASSERT_TRUE(pipe);
    std::string out;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe.get())) out += buffer;
    for (const char* line : {"codec_name=h264\n", "pix_fmt=yuv420p\n", "avg_frame_rate=30/1\n",
                             "duration=1.000000\n", "nb_read_frames=30\n"}) {
        EXPECT_NE(out.find(line), std::string::npos) << "missing " << line << "in\n" << out;
    }
}

// ---- WebM
// ----------------------------------------------------------------------------------------

TEST(WebmSink, PlaysAsVp9WithEveryFrameAndRepeatsExactly) {
    const fs::path dir = fresh_artifact_dir();
    for (const char* name : {"a.webm", "b.webm"}) {
        auto sink = open_sink((dir / name).string(), video_options());
        write_moving_frames(*sink, 64, 48);
        sink->finish();
    }
    EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"a.webm", "b.webm"}));
    const VideoFacts v = probe(dir / "a.webm");
    EXPECT_EQ(v.codec, "vp9");
    EXPECT_EQ(v.pix_fmt, "yuv420p");
    EXPECT_EQ(v.width, 64);
    EXPECT_EQ(v.height, 48);
    EXPECT_EQ(v.decoded_frames, 30);
    EXPECT_NEAR(v.container_seconds, 1.0, 1.0 / 30);
    EXPECT_EQ(v.space, AVCOL_SPC_BT709);
    EXPECT_TRUE(read_bytes(dir / "a.webm") == read_bytes(dir / "b.webm"));
}

} // namespace
} // namespace tumble::render
