// The tumble-shard tag a video carries: written and read back whole, and two shards of different
// runs told apart by the first setting in which they differ.
#include "app/cluster/shard_tag.h"
#include "io/bad_input.h"

#include <gtest/gtest.h>

namespace tumble::app {
namespace {

ShardTag some_tag() {
    const Scene scene = load_scene_argument("default");
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    return shard_tag_for(scene, tl, {60, 120}, 18, "medium");
}

TEST(ShardTag, ReadsBackWhatItWrites) {
    const ShardTag t = some_tag();
    EXPECT_EQ(t.frames, 600);
    EXPECT_EQ(t.key_interval, 120); // 2 s at 60 fps
    const std::string text = format_tag(t);
    EXPECT_TRUE(text.starts_with("tumble-shard/1 frames=60:120/600 scene=")) << text;
    const auto back = parse_tag(text, "part.mp4");
    ASSERT_TRUE(back);
    EXPECT_EQ(format_tag(*back), text);
    EXPECT_EQ(tag_mismatch(*back, t), "");
}

TEST(ShardTag, ShardsOfDifferentRunsDiffer) {
    const ShardTag t = some_tag();
    Scene other = load_scene_argument("default");
    const Timeline tl = make_timeline(other.world.dt, other.duration, other.render.fps);
    other.render.shadows = false; // --no-shadows: same file, other pictures
    EXPECT_NE(tag_mismatch(shard_tag_for(other, tl, {0, 60}, 18, "medium"), t).find("look"),
              std::string::npos);
    EXPECT_NE(
        tag_mismatch(shard_tag_for(load_scene_argument("dominoes"), tl, {0, 60}, 18, "medium"), t)
            .find("scene"),
        std::string::npos);
    ShardTag crf = t;
    crf.crf = 20;
    EXPECT_NE(tag_mismatch(crf, t).find("crf 20 against 18"), std::string::npos);
    ShardTag build = t;
    build.build = "0000";
    EXPECT_NE(tag_mismatch(build, t).find("build"), std::string::npos);
}

TEST(ShardTag, OtherCommentsAreNotTagsAndBrokenTagsAreRefused) {
    EXPECT_FALSE(parse_tag("", "a.mp4"));
    EXPECT_FALSE(parse_tag("made with something else", "a.mp4"));
    EXPECT_THROW(parse_tag("tumble-shard/2 frames=0:60/60", "a.mp4"), io::BadInput);
    EXPECT_THROW(parse_tag("tumble-shard/1 frames=60:0/600 scene=a look=b build=c size=2x2 fps=1 "
                           "codec=x crf=1 preset=p keyint=1",
                           "a.mp4"),
                 io::BadInput);
    EXPECT_THROW(parse_tag("tumble-shard/1 scene=a", "a.mp4"), io::BadInput);
}

} // namespace
} // namespace tumble::app
