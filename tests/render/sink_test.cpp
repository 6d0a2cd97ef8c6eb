// PNG sinks (file names, contents, what they leave on disk) and open_sink's choice of sink and
// its error messages.
#include "render/open_sink.h"
#include "render/png_io.h"
#include "render/png_sink.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace tumble::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_artifact_dir;
using test::list_dir;

SinkOptions video_options() {
    SinkOptions options;
    options.width = 64, options.height = 48, options.fps = 30;
    return options;
}

// ---- PNG sinks ---------------------------------------------------------------------------------

TEST(PngSequenceSink, DirectoryGivesSixDigitNames) {
    const fs::path dir = fresh_artifact_dir();
    auto sink = open_sink(dir.string(), {}); // an existing directory, no trailing slash
    EXPECT_EQ(sink->describe(), (dir / "%06d.png").string());
    std::vector<Image> frames;
    for (int k = 0; k < 3; ++k) frames.push_back(test::rendered_like(32, 24, k));
    for (const Image& frame : frames) sink->write(frame);
    sink->finish();
    EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"000000.png", "000001.png", "000002.png"}));
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(read_png(dir / list_dir(dir)[k]).rgb == frames[k].rgb) << "frame " << k;
    }
}

TEST(PngSequenceSink, TrailingSlashCreatesTheDirectory) {
    const fs::path dir = fresh_artifact_dir();
    auto sink = open_sink((dir / "new").string() + "/", {});
    sink->write(test::rendered_like(16, 12));
    sink->finish();
    EXPECT_EQ(list_dir(dir / "new"), std::vector<std::string>{"000000.png"});
}

TEST(PngSequenceSink, PatternsNameTheFiles) {
    const fs::path dir = fresh_artifact_dir();
    auto shots = open_sink((dir / "shot_%04d.png").string(), {});
    auto frames = open_sink((dir / "frames" / "%06d.png").string(), {}); // creates frames/
    auto plain = open_sink((dir / "p%d.PNG").string(), {});
    for (int k = 0; k < 11; ++k) {
        for (FrameSink* sink : {shots.get(), frames.get(), plain.get()}) {
            sink->write(test::rendered_like(8, 6));
        }
    }
    for (FrameSink* sink : {shots.get(), frames.get(), plain.get()}) sink->finish();
    EXPECT_TRUE(fs::exists(dir / "shot_0000.png"));
    EXPECT_TRUE(fs::exists(dir / "shot_0010.png"));
    EXPECT_TRUE(fs::exists(dir / "frames" / "000010.png"));
    EXPECT_TRUE(fs::exists(dir / "p10.PNG"));
    EXPECT_EQ(list_dir(dir / "frames").size(), 11u);
    EXPECT_EQ(list_dir(dir).size(), 11u + 1 + 11); // shots, frames/, plain: nothing hidden
}

TEST(PngSequenceSink, AbortRemovesItsFramesAndTheDirectoryItMade) {
    const fs::path dir = fresh_artifact_dir();
    std::ofstream(dir / "keep.txt") << "not ours";
    auto in_existing = open_sink(dir.string(), {});
    auto in_new = open_sink((dir / "made" / "%03d.png").string(), {});
    for (int k = 0; k < 4; ++k) {
        in_existing->write(test::rendered_like(8, 6));
        in_new->write(test::rendered_like(8, 6));
    }
    in_existing->abort();
    in_new.reset(); // the destructor aborts
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"keep.txt"});
}

TEST(PngSequenceSink, RefusesFramesOfAnotherSize) {
    auto sink = open_sink(fresh_artifact_dir().string(), {});
    sink->write(test::rendered_like(16, 12));
    EXPECT_THROW(sink->write(test::rendered_like(16, 10)), SinkError);
}

TEST(PngStillSink, WritesOneFrameAndRefusesASecond) {
    const fs::path dir = fresh_artifact_dir();
    auto sink = open_sink((dir / "still.png").string(), {});
    const Image frame = test::rendered_like(40, 30);
    sink->write(frame);
    EXPECT_TRUE(list_dir(dir).size() == 1 && list_dir(dir)[0] != "still.png"); // not yet final
    EXPECT_THROW(sink->write(frame), SinkError);
    sink->finish();
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"still.png"});
    EXPECT_TRUE(read_png(dir / "still.png").rgb == frame.rgb);
}

TEST(PngStillSink, NothingWithoutAFrameOrAfterAbort) {
    const fs::path dir = fresh_artifact_dir();
    auto empty = open_sink((dir / "empty.png").string(), {});
    EXPECT_THROW(empty->finish(), SinkError);
    auto aborted = open_sink((dir / "aborted.png").string(), {});
    aborted->write(test::rendered_like(8, 6));
    aborted->abort();
    EXPECT_TRUE(list_dir(dir).empty());
}

// ---- choosing a sink, and errors ---------------------------------------------------------------

// Expects open_sink(output) to throw SinkError whose message contains each of `parts`.
void expect_open_error(const std::string& output, std::vector<std::string> parts,
                       const SinkOptions& options = video_options()) {
    try {
        open_sink(output, options);
        ADD_FAILURE() << "no error for " << output;
    } catch (const SinkError& e) {
        for (const std::string& part : parts) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
                << "'" << part << "' not in: " << e.what();
        }
    }
}

TEST(OpenSink, UnknownExtensionListsWhatIsSupported) {
    const fs::path dir = fresh_artifact_dir();
    expect_open_error((dir / "out.avi").string(), {"out.avi", ".mp4", ".png", "%06d"});
    expect_open_error((dir / "out").string(), {"out", ".mp4"});
    expect_open_error((dir / "clip_%03d.mp4").string(), {"PNG only"});
    EXPECT_TRUE(list_dir(dir).empty());
}

TEST(OpenSink, BadPatternsAreExplained) {
    const fs::path dir = fresh_artifact_dir();
    expect_open_error((dir / "a_%s.png").string(), {"%06d"});
    expect_open_error((dir / "a_%d_%d.png").string(), {"more than one"});
    expect_open_error((dir / "run%d" / "a.png").string(), {"file name"});
    EXPECT_TRUE(list_dir(dir).empty());
}

TEST(OpenSink, UnwritableOrMissingDirectoryIsNamed) {
    const fs::path dir = fresh_artifact_dir();
    std::ofstream(dir / "file") << "a file, not a directory";
    for (const char* output : {"file/out.mp4", "file/out.png", "file/frames/", "file/%04d.png"}) {
        expect_open_error((dir / output).string(), {(dir / "file").string()});
    }
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"file"});
}

// One rule for every output (issue 14): missing parents are created, however deep.
TEST(OpenSink, MissingParentsAreCreated) {
    const fs::path dir = fresh_artifact_dir();
    auto still = open_sink((dir / "a" / "b" / "still.png").string(), {});
    still->write(test::rendered_like(16, 12));
    still->finish();
    auto frames = open_sink((dir / "c" / "d" / "frames").string() + "/", {});
    frames->write(test::rendered_like(16, 12));
    frames->finish();
    EXPECT_EQ(list_dir(dir / "a" / "b"), std::vector<std::string>{"still.png"});
    EXPECT_EQ(list_dir(dir / "c" / "d" / "frames"), std::vector<std::string>{"000000.png"});
}

// The files a pattern could have written: prefix, digits (zero-padded: at least the width), suffix.
TEST(FramePattern, ExistingFramesAreExactlyThePatternsFiles) {
    const fs::path dir = fresh_artifact_dir();
    for (const char* name : {"000000.png", "000017.png", "1234567.png", "12.png", "00000a.png",
                             "000003.jpg", "notes.txt", "x000001.png"})
        std::ofstream(dir / name) << "x";
    std::vector<std::string> found;
    for (const fs::path& p : FramePattern::in_directory(dir).existing_frames())
        found.push_back(p.filename().string());
    EXPECT_EQ(found, (std::vector<std::string>{"000000.png", "000017.png", "1234567.png"}));
    found.clear();
    for (const fs::path& p : FramePattern::parse((dir / "x%d.png").string())->existing_frames())
        found.push_back(p.filename().string());
    EXPECT_EQ(found, std::vector<std::string>{"x000001.png"});
}

// Six new frames over thirty old ones would leave 24 stale frames for a later `ffmpeg -i
// %06d.png` to play: refused, the old frames untouched; with overwrite, the old frames (and only
// files of the pattern) are removed first.
TEST(PngSequenceSink, AFolderWithFramesOfAnotherRunIsRefusedUnlessOverwrite) {
    const fs::path dir = fresh_artifact_dir();
    {
        auto old = open_sink(dir.string() + "/", {});
        for (int k = 0; k < 30; ++k) old->write(test::rendered_like(16, 12, k));
        old->finish();
    }
    std::ofstream(dir / "README.txt") << "keep me";
    expect_open_error(dir.string() + "/", {"30 frames", "--overwrite"});
    EXPECT_EQ(list_dir(dir).size(), 31u); // nothing removed
    SinkOptions options;
    options.overwrite = true;
    auto sink = open_sink(dir.string() + "/", options);
    for (int k = 0; k < 6; ++k) sink->write(test::rendered_like(16, 12, k));
    sink->finish();
    EXPECT_EQ(list_dir(dir),
              (std::vector<std::string>{"000000.png", "000001.png", "000002.png", "000003.png",
                                        "000004.png", "000005.png", "README.txt"}));
}

TEST(FramePattern, FormatsWidthPaddingAndPercent) {
    EXPECT_EQ(FramePattern::parse("f%d.png")->name(7), "f7.png");
    EXPECT_EQ(FramePattern::parse("f%3d.png")->name(7), "f  7.png");
    EXPECT_EQ(FramePattern::parse("f%03d.png")->name(1234), "f1234.png");
    EXPECT_EQ(FramePattern::parse("100%%_%02d.png")->name(5), "100%_05.png");
    EXPECT_FALSE(FramePattern::parse("plain.png").has_value());
}

} // namespace
} // namespace tumble::render
