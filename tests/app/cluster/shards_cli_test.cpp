// Shards as a user runs them: `tumble shards` prints the commands, each renders its frames (from
// checkpoints written by `tumble simulate --checkpoint-every`), `tumble join` puts the videos
// together, and the joined video decodes (with ffmpeg, an independent decoder) to exactly the
// frames of a single-process render. What does not belong together is refused, exit 2, nothing
// written.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <set>

namespace tumble::test {
namespace {

namespace fs = std::filesystem;

// 6 s at 10 fps (60 frames, a key frame every 2 s: 0, 20, 40) of 160x90: short, still moving.
const std::string kRun = "default --fps 10 --duration 6";
const std::string kLook = "--width 160 --height 90";

// Per decoded frame: its timestamp and the MD5 of its pixels (ffmpeg's framemd5).
std::vector<std::string> decoded_frames(const fs::path& dir, const std::string& video) {
    const CliResult r = run_shell(dir, "ffmpeg -v error -i '" + video + "' -f framemd5 -");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::vector<std::string> frames;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || line[0] == '#') continue;
        const auto comma = line.find(',');
        const auto hash = line.rfind(',');
        frames.push_back(line.substr(comma + 1, line.find(',', comma + 1) - comma - 1) + " " +
                         line.substr(hash + 1));
    }
    return frames;
}

TEST(ShardsCli, JoinedShardsDecodeToTheFramesOfASingleRender) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_tumble(dir, "render " + kRun + " " + kLook + " -q -o single.mp4").exit_code, 0);
    const CliResult ck = run_tumble(dir, "simulate " + kRun +
                                             " --checkpoint-every 20 "
                                             "--checkpoints ck -q");
    ASSERT_EQ(ck.exit_code, 0) << ck.err;
    EXPECT_EQ(files_in(dir / "ck"),
              (std::vector<std::string>{"frame_000020.tck", "frame_000040.tck"}));
    const CliResult plan =
        run_tumble(dir, "shards " + kRun +
                            " --count 3 -o out/joined.mp4 --from-checkpoints ck --tumble "
                            "\"$TUMBLE\" -q -- " +
                            kLook + " > plan.sh && sh plan.sh");
    ASSERT_EQ(plan.exit_code, 0) << plan.err;
    // Tumble's own lines (a sanitizer's report, e.g. LeakSanitizer's summary, is no concern here):
    // 6 a shard, its checkpoint note and its summary (with the contact effort's line).
    int said = 0;
    std::istringstream lines(plan.err);
    for (std::string line; std::getline(lines, line);) said += line.starts_with("tumble: ");
    EXPECT_EQ(said, 3 * 6) << "each shard prints its checkpoint note and its summary: " << plan.err;
    EXPECT_NE(plan.err.find("continuing from ck/frame_000040.tck (frame 40)"), std::string::npos);
    // Given out of order: the join sorts them by range.
    const CliResult join = run_tumble(dir, "join out/joined.part002.mp4 out/joined.part000.mp4 "
                                           "out/joined.part001.mp4 -o out/joined.mp4");
    ASSERT_EQ(join.exit_code, 0) << join.err;
    EXPECT_NE(join.err.find("joined 3 shards, frames 0:60 of 60"), std::string::npos) << join.err;
    const std::vector<std::string> single = decoded_frames(dir, "single.mp4");
    const std::vector<std::string> joined = decoded_frames(dir, "out/joined.mp4");
    ASSERT_EQ(single.size(), 60u);
    // Key frames every two seconds (20 frames), where the encoder starts afresh: the only places a
    // shard may start.
    const CliResult keys = run_shell(dir, "ffprobe -v error -show_entries frame=key_frame -of "
                                          "csv=p=0 single.mp4");
    std::istringstream flags(keys.out);
    std::vector<int> key_frames;
    int index = 0;
    for (std::string flag; std::getline(flags, flag);) {
        if (flag.empty() || !std::isdigit(static_cast<unsigned char>(flag[0])))
            continue; // side data
        if (flag[0] == '1') key_frames.push_back(index);
        ++index;
    }
    EXPECT_EQ(index, 60);
    ASSERT_GE(key_frames.size(), 3u) << keys.out;
    for (const int k : {0, 20, 40})
        EXPECT_NE(std::find(key_frames.begin(), key_frames.end(), k), key_frames.end()) << k;
    EXPECT_GT(std::set<std::string>(single.begin(), single.end()).size(), 50u)
        << "the frames must differ from each other for the comparison to mean something";
    EXPECT_EQ(joined, single);
    // A shard continued from a checkpoint is the same file as one simulated from t = 0.
    ASSERT_EQ(run_tumble(dir, "render " + kRun + " " + kLook + " --frames 40:60 -q -o fresh.mp4")
                  .exit_code,
              0);
    EXPECT_EQ(read_text(dir / "fresh.mp4"), read_text(dir / "out/joined.part002.mp4"));
}

TEST(ShardsCli, JoinRefusesShardsThatDoNotBelongTogether) {
    const auto dir = scratch_dir();
    const std::string render = "render " + kRun + " " + kLook + " -q ";
    for (const std::string first : {"0", "20", "40"})
        ASSERT_EQ(run_tumble(dir, render + "--frames " + first + ":" +
                                      std::to_string(std::stoi(first) + 20) + " -o p" + first +
                                      ".mp4")
                      .exit_code,
                  0);
    ASSERT_EQ(run_tumble(dir, render + "--frames 20:40 --crf 20 -o crf.mp4").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, "render dominoes --fps 10 --duration 6 " + kLook +
                                  " -q --frames 20:40 -o other.mp4")
                  .exit_code,
              0);
    ASSERT_EQ(run_shell(dir, "ffmpeg -v error -f lavfi -i testsrc=size=160x90:rate=10 -t 2 "
                             "-c:v libx264 plain.mp4")
                  .exit_code,
              0);
    // A shard whose tag claims more frames than it holds (a render stopped by Ctrl-C).
    ASSERT_EQ(run_shell(dir, "ffmpeg -v error -i p20.mp4 -c copy -metadata comment=\"$(ffprobe "
                             "-v error -show_entries format_tags=comment -of "
                             "default=nw=1:nk=1 p20.mp4 | sed 's/20:40/20:60/')\" short.mp4")
                  .exit_code,
              0);
    const auto refused = [&](const std::string& parts, const char* words) {
        const CliResult r = run_tumble(dir, "join " + parts + " -o joined.mp4");
        EXPECT_EQ(r.exit_code, 2) << parts << ": " << r.err;
        EXPECT_NE(r.err.find(words), std::string::npos) << parts << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir / "joined.mp4")) << parts;
    };
    refused("p0.mp4 p40.mp4", "(frames 0:20) and p40.mp4 (frames 40:60) leave a gap");
    refused("p0.mp4 p20.mp4 p20.mp4", "overlap");
    refused("p0.mp4 crf.mp4 p40.mp4", "crf 20 against 18");
    refused("p0.mp4 other.mp4 p40.mp4", "not shards of the same run: scene");
    refused("p0.mp4 plain.mp4", "plain.mp4: not a shard made by `tumble render`");
    refused("p0.mp4 short.mp4", "short.mp4: holds 20 frames, but its tag says frames 20:60");
    refused("p0.mp4 missing.mp4", "missing.mp4: no such file");
    for (const auto& f : fs::directory_iterator(dir))
        EXPECT_FALSE(f.path().filename().string().starts_with(".joined")) << "a temporary left";
    EXPECT_EQ(run_tumble(dir, "join p40.mp4 p0.mp4 p20.mp4 -o joined.mp4 -q").exit_code, 0);
}

TEST(ShardsCli, PngShardsFillOneFolderWithTheFramesOfAWholeRender) {
    const auto dir = scratch_dir();
    const std::string render = "render " + kRun + " " + kLook + " -q ";
    ASSERT_EQ(run_tumble(dir, render + "-o whole/").exit_code, 0);
    // PNG shards may start anywhere: no key frames, no join.
    ASSERT_EQ(run_tumble(dir, render + "--frames 25:60 -o parts/").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, render + "--frames 0:25 -o parts/").exit_code, 0);
    const std::vector<std::string> whole = files_in(dir / "whole");
    ASSERT_EQ(whole.size(), 60u);
    EXPECT_EQ(files_in(dir / "parts"), whole);
    for (const std::string& f : whole)
        EXPECT_EQ(read_text(dir / "parts" / f), read_text(dir / "whole" / f)) << f;
    // A shard refuses frames of its own range already there, and only those.
    const CliResult again = run_tumble(dir, render + "--frames 20:30 -o parts/");
    EXPECT_EQ(again.exit_code, 2);
    EXPECT_NE(again.err.find("10 frames"), std::string::npos) << again.err;
}

TEST(ShardsCli, ShardsPrintsOneCommandPerShardAndTheJoin) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "shards default --count 4 -o 'my run.mp4' -- --width 640");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // 600 frames are 5 two-second segments of 120: 4 shards take 2, 1, 1 and 1 of them.
    EXPECT_EQ(r.out,
              "tumble render default --frames 0:240 -o 'my run.part000.mp4' --width 640\n"
              "tumble render default --frames 240:360 -o 'my run.part001.mp4' --width 640\n"
              "tumble render default --frames 360:480 -o 'my run.part002.mp4' --width 640\n"
              "tumble render default --frames 480:600 -o 'my run.part003.mp4' --width 640\n");
    const CliResult join = run_tumble(dir, "shards default --count 4 -o 'my run.mp4' --join");
    EXPECT_EQ(join.out, "tumble join 'my run.part000.mp4' 'my run.part001.mp4' 'my "
                        "run.part002.mp4' 'my run.part003.mp4' -o 'my run.mp4'\n");
    const CliResult own = run_tumble(dir, "shards default --count 2 -- --fps 30");
    EXPECT_EQ(own.exit_code, 2);
    EXPECT_NE(own.err.find("give --fps to `tumble shards` itself"), std::string::npos) << own.err;
    EXPECT_EQ(run_tumble(dir, "shards default --count 6").exit_code, 2); // 5 segments
}

TEST(ShardsCli, RenderRefusesRangesOffKeyFramesAndOutputsThatCannotBeShards) {
    const auto dir = scratch_dir();
    const std::string render = "render " + kRun + " " + kLook + " -q ";
    for (const std::string& bad :
         {std::string("--frames 10:30 -o a.mp4"), std::string("--frames 0:20 -o a.webm"),
          std::string("--frames 0:20 -o a.gif"), std::string("--frames 0:61 -o a.mp4"),
          std::string("--frames 0:20 --frame 3 -o a.png")}) {
        const CliResult r = run_tumble(dir, render + bad);
        EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    }
    EXPECT_TRUE(files_in(dir).empty());
    const CliResult named = run_tumble(dir, render + "--frames 20:40");
    ASSERT_EQ(named.exit_code, 0) << named.err;
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"default_000020-000040.mp4"}));
}

TEST(CheckpointCli, ACheckpointOfAnotherRunIsRefusedAndNothingIsWritten) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_tumble(dir, "simulate " + kRun + " --checkpoint-every 20 --checkpoints ck -q")
                  .exit_code,
              0);
    const auto refused = [&](const std::string& args, const char* words) {
        const CliResult r = run_tumble(dir, args + " -o out.mp4");
        EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
        EXPECT_NE(r.err.find(words), std::string::npos) << args << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir / "out.mp4"));
    };
    const std::string from = " " + kLook + " --frames 40:60 --from-checkpoints ck";
    refused("render dominoes --fps 10 --duration 6" + from, "made from another scene");
    refused("render " + kRun + " --integrator euler" + from, "integrator rk4, this run uses euler");
    refused("render " + kRun + " --dt 0.001" + from, "it was made with step");
    refused("render " + kRun + " " + kLook + " --frames 40:60 --from-checkpoints nowhere",
            "no such directory");
    write_text(dir / "ck/frame_000040.tck", "TUMBLECK garbage");
    refused("render " + kRun + from, "ck/frame_000040.tck: not a checkpoint this tumble can read");
    const CliResult none = run_tumble(dir, "simulate default -q");
    EXPECT_EQ(none.exit_code, 2);
    EXPECT_NE(none.err.find("expected -o FILE"), std::string::npos) << none.err;
}

} // namespace
} // namespace tumble::test
