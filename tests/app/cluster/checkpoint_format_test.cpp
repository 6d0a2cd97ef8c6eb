// The checkpoint file format: every field comes back with its bits, and whatever is not a whole
// checkpoint of this run is refused with a message naming the file and the reason, never a crash
// or a silent partial state.
#include "app/cluster/checkpoint.h"
#include "app/cluster/checkpoint_store.h"
#include "app/run/simulation.h"
#include "app/scene/scene.h"
#include "physics/scenes/sphere_rain.h"
#include "physics/state_fields.h"
#include "physics/step.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

namespace tumble::app {
namespace {

// A state with contacts and sleeping bodies, after 150 steps of a small sphere pile.
struct Pile {
    physics::Model model;
    physics::State state;
    Pile() {
        scenes::Scene s = scenes::sphere_rain(3);
        s.world.contact.sleeping = true;
        model = physics::build_model(s.world, s.bodies);
        state = physics::initial_state(model, s.bodies);
        for (int k = 0; k < 150; ++k) physics::step(model, state);
    }
};

CheckpointHeader some_header() {
    CheckpointHeader h;
    h.scene_hash = 0x0123456789abcdefull;
    h.build = "abc123";
    h.integrator = "rk4";
    h.h = 1.0 / 240.0;
    h.fps = 60;
    h.steps_per_frame = 4;
    h.frame = 37;
    h.bodies = 32;
    return h;
}

TEST(CheckpointFormat, EveryFieldComesBackWithItsBits) {
    Pile p;
    ASSERT_GT(p.state.contacts.size(), 0);
    // Values a decimal text format would lose or blur: -0, the smallest subnormal, one ulp.
    p.state.x_carry[5].x() = -0.0;
    p.state.x_carry[6].y() = std::numeric_limits<double>::denorm_min();
    p.state.sleep.slow_time[7] = std::nextafter(0.25, 1.0);
    const Checkpoint c = decode_checkpoint(encode_checkpoint(some_header(), p.state), "mem");
    EXPECT_EQ(c.header.scene_hash, some_header().scene_hash);
    EXPECT_EQ(c.header.build, "abc123");
    EXPECT_EQ(c.header.integrator, "rk4");
    EXPECT_EQ(c.header.h, 1.0 / 240.0);
    EXPECT_EQ(c.header.frame, 37);
    // Field by field, each compared as bytes of its own (independent of the format's encoding).
    int fields = 0;
    physics::for_each_field(p.state, [&](const char* name, const auto& saved) {
        ++fields;
        physics::for_each_field(c.state, [&](const char* other, const auto& loaded) {
            if (std::string_view(name) != other) return;
            using A = std::decay_t<decltype(saved)>;
            using B = std::decay_t<decltype(loaded)>;
            if constexpr (std::is_same_v<A, B>) {
                if constexpr (std::is_same_v<A, std::vector<physics::CachedPoint>>) {
                    ASSERT_EQ(saved.size(), loaded.size());
                    for (std::size_t i = 0; i < saved.size(); ++i) {
                        EXPECT_EQ(std::memcmp(saved[i].point.data(), loaded[i].point.data(), 24),
                                  0);
                        EXPECT_EQ(saved[i].id, loaded[i].id);
                        EXPECT_EQ(
                            std::memcmp(&saved[i].normal_impulse, &loaded[i].normal_impulse, 8), 0);
                        EXPECT_EQ(std::memcmp(saved[i].friction_impulse.data(),
                                              loaded[i].friction_impulse.data(), 24),
                                  0);
                        EXPECT_EQ(std::memcmp(&saved[i].separation, &loaded[i].separation, 8), 0);
                    }
                } else if constexpr (std::is_same_v<A, std::int64_t>) {
                    EXPECT_EQ(saved, loaded) << name;
                } else {
                    ASSERT_EQ(saved.size(), loaded.size()) << name;
                    EXPECT_EQ(
                        std::memcmp(saved.data(), loaded.data(), saved.size() * sizeof(saved[0])),
                        0)
                        << name;
                }
            }
        });
    });
    EXPECT_EQ(fields, 14);
    EXPECT_EQ(physics::state_mismatch(p.model, c.state), "");
}

TEST(CheckpointFormat, EveryTruncationAndDamageIsRefusedNamingTheFile) {
    Pile p;
    const std::string bytes = encode_checkpoint(some_header(), p.state);
    for (std::size_t n = 0; n < bytes.size(); n += 1 + n / 64) {
        try {
            decode_checkpoint(bytes.substr(0, n), "ck/frame_000037.tck");
            ADD_FAILURE() << "a checkpoint cut at " << n << " of " << bytes.size() << " bytes";
        } catch (const CheckpointError& e) {
            EXPECT_NE(std::string(e.what()).find("ck/frame_000037.tck"), std::string::npos);
        }
    }
    for (std::size_t at : {std::size_t{9}, std::size_t{40}, bytes.size() / 2, bytes.size() - 3}) {
        std::string damaged = bytes;
        damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
        EXPECT_THROW(decode_checkpoint(damaged, "x"), CheckpointError) << "byte " << at;
    }
    try {
        decode_checkpoint(std::string("TUMBLECK\x02\0\0\0", 12) + bytes.substr(12), "x.tck");
        ADD_FAILURE() << "another format version";
    } catch (const CheckpointError& e) {
        EXPECT_NE(std::string(e.what()).find("format version 2"), std::string::npos) << e.what();
    }
    EXPECT_THROW(decode_checkpoint("{\"not\": \"a checkpoint\"}", "x"), CheckpointError);
}

TEST(CheckpointFormat, AHeaderOfAnotherRunSaysWhatDiffers) {
    const CheckpointHeader run = some_header();
    EXPECT_EQ(header_mismatch(run, run), "");
    auto differs = [&](auto change, const char* words) {
        CheckpointHeader other = run;
        change(other);
        const std::string why = header_mismatch(other, run);
        EXPECT_NE(why.find(words), std::string::npos) << why;
    };
    differs([](CheckpointHeader& h) { h.scene_hash ^= 1; }, "another scene");
    differs([](CheckpointHeader& h) { h.build = "other"; }, "another build of tumble");
    differs([](CheckpointHeader& h) { h.integrator = "euler"; }, "integrator euler");
    differs([](CheckpointHeader& h) { h.h = std::nextafter(h.h, 1.0); }, "step");
    differs([](CheckpointHeader& h) { h.fps = 30; }, "30 fps");
    differs([](CheckpointHeader& h) { h.bodies = 3; }, "3 bodies");
}

TEST(CheckpointFormat, AStateThatDoesNotFitTheModelIsNamed) {
    Pile p;
    physics::State s = p.state;
    s.v.pop_back();
    EXPECT_NE(physics::state_mismatch(p.model, s).find("v has"), std::string::npos);
    s = p.state;
    ASSERT_GT(s.contacts.size(), 0);
    s.contacts.pair[0] = physics::pair_key(3, 1);
    EXPECT_NE(physics::state_mismatch(p.model, s).find("contact manifold 0"), std::string::npos);
    s = p.state;
    s.contacts.points.pop_back();
    EXPECT_NE(physics::state_mismatch(p.model, s).find("contacts.points"), std::string::npos);
    s = p.state;
    s.sleep.asleep[3] = 2;
    EXPECT_NE(physics::state_mismatch(p.model, s).find("sleep.asleep of body 3"),
              std::string::npos);
}

// Through the folder: a checkpoint named for one frame but holding another's state, and one of
// another scene, are refused; a folder without one at or before the frame gives nothing.
TEST(CheckpointFormat, TheFolderRefusesCheckpointsOfAnotherRun) {
    const auto dir = std::filesystem::path(TUMBLE_TEST_ARTIFACTS) / "checkpoint_format";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const Scene scene = load_scene_argument("default");
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    Simulation sim = make_simulation(scene, tl.h);
    for (int k = 0; k < 10 * tl.steps_per_frame; ++k) sim.step();
    save_checkpoint(dir, scene, tl, sim, 10);
    EXPECT_FALSE(nearest_checkpoint(dir, 9, scene, tl, sim));
    EXPECT_EQ(nearest_checkpoint(dir, 25, scene, tl, sim)->frame, 10);
    std::filesystem::rename(checkpoint_path(dir, 10), checkpoint_path(dir, 20));
    EXPECT_THROW(nearest_checkpoint(dir, 25, scene, tl, sim), CheckpointError);
    std::filesystem::remove(checkpoint_path(dir, 20));
    const Scene other = load_scene_argument("dominoes");
    const Timeline other_tl = make_timeline(other.world.dt, other.duration, other.render.fps);
    Simulation other_sim = make_simulation(other, other_tl.h);
    save_checkpoint(dir, other, other_tl, other_sim, 0);
    try {
        nearest_checkpoint(dir, 5, scene, tl, sim);
        ADD_FAILURE() << "a checkpoint of dominoes continued the default scene";
    } catch (const CheckpointError& e) {
        EXPECT_NE(std::string(e.what()).find("another scene"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("frame_000000.tck"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace tumble::app
