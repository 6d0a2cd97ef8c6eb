// The MP4 a user gets: frame count, frame rate, duration and pixel format as written in the
// container (read back with ffprobe, as a user would check), and Ctrl-C finishing a video that
// still plays.
#include "support/cli_runner.h"
#include "support/interrupt_runner.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <map>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace tumble::test {
namespace {

// key=value lines of `ffprobe -count_frames` for the first video stream.
std::map<std::string, std::string> probe(const std::filesystem::path& file) {
    const auto out = file.parent_path() / "probe.txt";
    const std::string cmd = "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
                            "stream=codec_name,pix_fmt,width,height,r_frame_rate,avg_frame_rate,"
                            "nb_read_frames:format=duration -of default=noprint_wrappers=1 '" +
                            file.string() + "' > '" + out.string() + "' 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << read_text(out);
    std::map<std::string, std::string> kv;
    std::istringstream in(read_text(out));
    std::string line;
    while (std::getline(in, line))
        if (auto eq = line.find('='); eq != std::string::npos)
            kv[line.substr(0, eq)] = line.substr(eq + 1);
    std::filesystem::remove(out);
    return kv;
}

TEST(Video, ContainerHasExactFrameCountRateDurationAndPixelFormat) {
    const auto dir = scratch_dir();
    const CliResult r =
        run_tumble(dir, "render --duration 1.5 --width 160 --height 90 --fps 30 -o v/out.mp4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("wrote v/out.mp4"), std::string::npos) << r.err;
    EXPECT_EQ(files_in(dir), std::vector<std::string>{"v/out.mp4"}); // no temporary left behind
    auto kv = probe(dir / "v/out.mp4");
    EXPECT_EQ(kv["codec_name"], "h264");
    EXPECT_EQ(kv["pix_fmt"], "yuv420p");
    EXPECT_EQ(kv["width"], "160");
    EXPECT_EQ(kv["height"], "90");
    EXPECT_EQ(kv["r_frame_rate"], "30/1");
    EXPECT_EQ(kv["avg_frame_rate"], "30/1");
    EXPECT_EQ(kv["nb_read_frames"], "45");
    EXPECT_NEAR(std::stod(kv["duration"]), 1.5, 1e-6);
}

// A FIFO cannot seek, so the MP4 streamed into one is fragmented (io/output_target.h); what
// comes out of the pipe must still be a complete video with every frame.
TEST(Video, AVideoStreamedIntoAFifoPlaysWithEveryFrame) {
    const auto dir = scratch_dir();
    ASSERT_EQ(mkfifo((dir / "pipe.mp4").c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = read_text(dir / "pipe.mp4"); });
    const CliResult r =
        run_tumble(dir, "render --duration 1 --width 160 --height 90 --fps 30 -o pipe.mp4 -q");
    reader.join();
    ASSERT_EQ(r.exit_code, 0) << r.err;
    write_text(dir / "received.mp4", received);
    auto kv = probe(dir / "received.mp4");
    EXPECT_EQ(kv["codec_name"], "h264");
    EXPECT_EQ(kv["nb_read_frames"], "30");
    EXPECT_NEAR(std::stod(kv["duration"]), 1.0, 1e-3);
}

TEST(Video, InterruptFinishesAPlayableVideoAndSaysSo) {
    const auto dir = scratch_dir();
    // Interrupt once encoded frames are reaching the (partial) file, however long start-up took
    // on a busy machine: x264 holds a few frames back, so a non-empty file means frames drawn.
    EXPECT_EQ(interrupt_when_writing(dir,
                                     "render --duration 600 --width 320 --height 180 -o "
                                     "long.mp4",
                                     ".long.mp4", SIGINT),
              130);
    const std::string err = read_text(dir / "stderr.txt");
    EXPECT_NE(err.find("interrupted"), std::string::npos) << err;
    ASSERT_TRUE(std::filesystem::exists(dir / "long.mp4")) << err;
    auto kv = probe(dir / "long.mp4");
    const int frames = std::stoi(kv["nb_read_frames"]);
    EXPECT_GT(frames, 0);
    EXPECT_NE(err.find("after " + std::to_string(frames) + " frames"), std::string::npos) << err;
    EXPECT_NEAR(std::stod(kv["duration"]), frames / 60.0, 1e-3); // format duration is in ms
}

// libx264 writes its settings into the stream (an SEI message: "... subme=0 ... me=dia ..." for
// ultrafast, "subme=2 ... me=hex" for veryfast), so the preset a run used can be read back.
TEST(Video, PreviewEncodesUltrafastUnlessAPresetIsGiven) {
    const auto dir = scratch_dir();
    CliResult r = run_tumble(dir, "render --preview --duration 0.1 -o p.mp4 -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run_tumble(dir, "render --preview --preset veryfast --duration 0.1 -o v.mp4 -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string p = read_text(dir / "p.mp4"), v = read_text(dir / "v.mp4");
    EXPECT_NE(p.find("subme=0"), std::string::npos);
    EXPECT_NE(p.find("me=dia"), std::string::npos);
    EXPECT_NE(v.find("subme=2"), std::string::npos);
    EXPECT_NE(v.find("me=hex"), std::string::npos);
}

} // namespace
} // namespace tumble::test
