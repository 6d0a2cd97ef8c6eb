// Checkpoints resume bit-identically: a run stopped at frame K, its State written to checkpoint
// bytes and read back into a fresh State with a fresh workspace, continues exactly as the run that
// never stopped. Compared at every later frame on every body's x, q, v, w (the bits, memcmp), and
// at the end on the whole State (its checkpoint bytes, which hold every field). Scenes: contact
// scenes with sleeping on (a pile of spheres that falls asleep, a box resting on a ramp, a stack),
// the free-body scenes with several integrators, and built-in scene files through the app's
// checkpoint folder, at several K.
#include "app/cluster/checkpoint.h"
#include "app/cluster/checkpoint_store.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "physics/scenes/contact_scenes.h"
#include "physics/scenes/reference_scenes.h"
#include "physics/scenes/sphere_rain.h"
#include "physics/step.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <vector>

namespace tumble::app {
namespace {

constexpr int kStepsPerFrame = 4;

struct Run {
    physics::Model model;
    physics::State state;
};

Run start(const scenes::Scene& scene, physics::Integrator integrator) {
    Run r;
    physics::WorldDef world = scene.world;
    world.integrator = integrator;
    r.model = physics::build_model(world, scene.bodies);
    r.state = physics::initial_state(r.model, scene.bodies);
    return r;
}

void step_frame(const Run& r, physics::State& s, physics::StepWorkspace& ws) {
    for (int k = 0; k < kStepsPerFrame; ++k) physics::step(r.model, s, ws);
}

// The bits of every body's pose and velocities.
bool same_motion(const physics::State& a, const physics::State& b) {
    const auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() &&
               std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
    };
    return a.step == b.step && same(a.x, b.x) && same(a.q, b.q) && same(a.v, b.v) && same(a.w, b.w);
}

CheckpointHeader header_for(const Run& r, std::int64_t frame) {
    CheckpointHeader h;
    h.build = "test";
    h.integrator = "any";
    h.h = r.model.dt;
    h.fps = 60;
    h.steps_per_frame = kStepsPerFrame;
    h.frame = frame;
    h.bodies = r.model.body_count();
    return h;
}

struct Resumed {
    int asleep_at_checkpoints = 0;   // sleeping bodies summed over the checkpoints
    int contacts_at_checkpoints = 0; // cached manifolds summed over the checkpoints
};

// Runs `frames` frames straight, then again stopping at each frame of `stops`, through the
// checkpoint bytes, comparing every later frame with the straight run.
Resumed check_resume(const scenes::Scene& scene, physics::Integrator integrator, int frames,
                     const std::vector<int>& stops) {
    Resumed out;
    Run straight = start(scene, integrator);
    std::vector<physics::State> reference{straight.state};
    physics::StepWorkspace ws(1);
    for (int f = 1; f <= frames; ++f) {
        step_frame(straight, straight.state, ws);
        reference.push_back(straight.state);
    }
    for (const int stop : stops) {
        SCOPED_TRACE(scene.name + ", stopped at frame " + std::to_string(stop));
        const physics::State& at = reference[stop];
        out.asleep_at_checkpoints +=
            std::accumulate(at.sleep.asleep.begin(), at.sleep.asleep.end(), 0);
        out.contacts_at_checkpoints += at.contacts.size();
        const std::string bytes = encode_checkpoint(header_for(straight, stop), at);
        Checkpoint c = decode_checkpoint(bytes, "memory");
        EXPECT_EQ(c.header.frame, stop);
        physics::StepWorkspace fresh(1); // nothing carried over but the bytes
        for (int f = stop + 1; f <= frames; ++f) {
            step_frame(straight, c.state, fresh);
            if (!same_motion(c.state, reference[f])) {
                ADD_FAILURE() << "first differs at frame " << f;
                break;
            }
        }
        EXPECT_EQ(encode_checkpoint(header_for(straight, frames), c.state),
                  encode_checkpoint(header_for(straight, frames), reference[frames]))
            << "the whole state (contacts, sleep, carries) at the last frame";
    }
    return out;
}

TEST(CheckpointResume, APileOfSpheresContinuesBitIdentically) {
    // Spheres roll (no rolling resistance), so this pile keeps moving with sleeping on; it is the
    // scene of many contacts with warm starts. The boxes below are the ones that fall asleep.
    scenes::Scene rain = scenes::sphere_rain(4); // 64 spheres
    rain.world.contact.sleeping = true;
    const Resumed r = check_resume(rain, physics::Integrator::Rk4, 240, {1, 37, 120, 200});
    EXPECT_GT(r.contacts_at_checkpoints, 100);
}

TEST(CheckpointResume, APyramidFallingAsleepContinuesBitIdentically) {
    scenes::Scene pyramid = scenes::pyramid(1.0 / 240.0); // 20 boxes
    pyramid.world.contact.sleeping = true;
    const Resumed r = check_resume(pyramid, physics::Integrator::Rk4, 240, {1, 37, 120, 200});
    // The checkpoints caught the pyramid in contact and, later, asleep: what the test is about.
    EXPECT_GT(r.contacts_at_checkpoints, 50);
    EXPECT_GT(r.asleep_at_checkpoints, 10);
}

TEST(CheckpointResume, ContactScenesWithSleepingContinueBitIdentically) {
    scenes::Scene stack = scenes::box_stack(4, 0.2, 1.0 / 240.0);
    stack.world.contact.sleeping = true;
    const scenes::Scene ramp = scenes::incline(0.3, 0.5, 1.0 / 240.0, true);
    for (const scenes::Scene& s : {stack, ramp}) {
        const Resumed r = check_resume(s, physics::Integrator::Splitting, 150, {1, 45, 140});
        EXPECT_GT(r.contacts_at_checkpoints, 0) << s.name;
        EXPECT_GT(r.asleep_at_checkpoints, 0) << s.name << ": no body was asleep at a checkpoint";
    }
}

TEST(CheckpointResume, FreeBodyScenesContinueBitIdenticallyWithEveryIntegrator) {
    const std::vector<scenes::Scene> free = {
        scenes::intermediate_axis_scene(), scenes::tumbling_box_scene(),
        scenes::gravity_spin_scene(), scenes::torque_free_spheres(4)};
    for (int i = 0; i < static_cast<int>(physics::Integrator::Count); ++i) {
        const auto id = static_cast<physics::Integrator>(i);
        for (scenes::Scene s : free) {
            // `exact` refuses applied torques (the gravity-and-spin ball's): without them here.
            if (physics::integrator_info(id).refuses_torque)
                for (physics::BodyDef& b : s.bodies) b.applied_torque = physics::Vec3::Zero();
            check_resume(s, id, 60, {1, 7, 59});
        }
    }
}

// The app's path: a built-in scene file, its Simulation, checkpoints written to a folder and the
// nearest one found and checked, at K = 1, 13 and 60 frames.
TEST(CheckpointResume, BuiltInScenesResumeFromTheCheckpointFolder) {
    const auto dir = std::filesystem::path(TUMBLE_TEST_ARTIFACTS) / "checkpoint_resume";
    for (const char* name : {"default", "dominoes", "tossed_book"}) {
        Scene scene = load_scene_argument(name);
        scene.duration = 2.0;
        const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
        Simulation straight = make_simulation(scene, tl.h);
        std::vector<physics::State> reference{straight.state};
        for (std::int64_t f = 1; f < tl.frames; ++f) {
            for (int k = 0; k < tl.steps_per_frame; ++k) straight.step();
            reference.push_back(straight.state);
        }
        for (const int every : {1, 13, 60}) {
            SCOPED_TRACE(std::string(name) + ", every " + std::to_string(every) + " frames");
            std::filesystem::remove_all(dir);
            std::filesystem::create_directories(dir);
            Simulation writer = make_simulation(scene, tl.h);
            for (std::int64_t f = every; f < tl.frames; f += every) {
                writer.state = reference[f];
                save_checkpoint(dir, scene, tl, writer, f);
            }
            const std::int64_t wanted = tl.frames - 7; // not itself a checkpoint unless every 1
            Simulation sim = make_simulation(scene, tl.h);
            const auto resume = nearest_checkpoint(dir, wanted, scene, tl, sim);
            ASSERT_TRUE(resume);
            EXPECT_EQ(resume->frame, wanted / every * every);
            sim.state = resume->state;
            for (std::int64_t f = resume->frame + 1; f < tl.frames; ++f) {
                for (int k = 0; k < tl.steps_per_frame; ++k) sim.step();
                ASSERT_TRUE(same_motion(sim.state, reference[f])) << "at frame " << f;
            }
        }
    }
}

} // namespace
} // namespace tumble::app
