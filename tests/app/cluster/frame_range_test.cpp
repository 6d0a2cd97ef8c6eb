// Shard ranges: --frames A:B is half-open, starts and ends on key frames for a video, and
// `tumble shards` tiles a run with ranges of whole key-frame segments.
#include "app/cluster/frame_range.h"
#include "io/bad_input.h"

#include <gtest/gtest.h>

namespace tumble::app {
namespace {

TEST(FrameRange, HalfOpenRangesOnKeyFrames) {
    const FrameRange r = parse_frame_range("--frames", "60:120", 600, 60);
    EXPECT_EQ(r.first, 60);
    EXPECT_EQ(r.end, 120);
    EXPECT_EQ(r.size(), 60);
    EXPECT_EQ(parse_frame_range("--frames", "540:600", 600, 60).size(), 60);
    EXPECT_EQ(parse_frame_range("--frames", "540:590", 590, 60).end, 590); // the run's end
    EXPECT_EQ(parse_frame_range("--frames", "7:9", 600, 1).size(), 2);     // PNG: any range
}

TEST(FrameRange, BadRangesAreRefusedSayingWhatIsExpected) {
    const auto refused = [](const std::string& text, int keys, const char* words) {
        try {
            parse_frame_range("--frames", text, 600, keys);
            ADD_FAILURE() << text << " was accepted";
        } catch (const io::BadInput& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("--frames " + text), std::string::npos);
        }
    };
    refused("60", 60, "expected FIRST:END");
    refused("a:b", 60, "expected FIRST:END");
    refused("60:60", 60, "0 <= FIRST < END <= 600");
    refused("120:60", 60, "0 <= FIRST < END <= 600");
    refused("0:660", 60, "0 <= FIRST < END <= 600");
    refused("-60:0", 60, "0 <= FIRST < END");
    refused("30:90", 60, "multiples of 60");
    refused("60:100", 60, "multiples of 60");
}

TEST(FrameRange, SplitTilesTheRunOnKeyFrames) {
    for (const std::int64_t frames : {1, 59, 60, 61, 600, 601, 1000})
        for (const int count : {1, 2, 3, 4, 7}) {
            const std::int64_t segments = (frames + 59) / 60;
            if (count > segments) {
                EXPECT_THROW(split_frames(frames, 60, count), io::BadInput);
                continue;
            }
            const std::vector<FrameRange> r = split_frames(frames, 60, count);
            ASSERT_EQ(static_cast<int>(r.size()), count);
            EXPECT_EQ(r.front().first, 0);
            EXPECT_EQ(r.back().end, frames);
            std::int64_t smallest = frames, largest = 0;
            for (std::size_t i = 0; i < r.size(); ++i) {
                EXPECT_EQ(r[i].first % 60, 0);
                EXPECT_GT(r[i].size(), 0);
                if (i > 0) {
                    EXPECT_EQ(r[i].first, r[i - 1].end);
                }
                if (i + 1 < r.size()) {
                    smallest = std::min(smallest, r[i].size());
                    largest = std::max(largest, r[i].size());
                }
            }
            EXPECT_LE(largest - smallest, 60) << "shards differ by at most one segment";
        }
    EXPECT_THROW(split_frames(600, 60, 0), io::BadInput);
}

} // namespace
} // namespace tumble::app
