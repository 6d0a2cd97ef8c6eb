// The integrator runs on the contact stage's threads, each worker over a fixed range of bodies
// (ContactStage::integrate_all). A failure on any worker must surface on the calling thread as
// the same DivergenceError a single thread gives: the first failing body in body order, the same
// step. (A C++ exception escaping a pool worker would end the program instead.)
#include "physics/build.h"
#include "physics/step.h"

#include <gtest/gtest.h>

#include <optional>

namespace tumble::physics {
namespace {

// A floor and 600 boxes 40 m apart high above it, with the contact stage forced on (nothing can
// touch: a fast box's speculative margin, h |w| swing, reaches 19 m; at 1 m apart its neighbours
// were contacts whose impulses slowed it before midpoint could fail),
// spinning gently near their middle axis, except two spinning so fast (h |w| = 50) that
// midpoint's Newton solve gives up within a few steps: one in each half of the body list.
struct Failing {
    Model model;
    State state;
    static constexpr int kFirst = 1 + 150, kSecond = 1 + 450; // body indices (0 is the floor)
    Failing() {
        WorldDef world;
        world.dt = 0.5;
        world.integrator = Integrator::Midpoint;
        world.gravity = Vec3::Zero();
        world.contact.parallel_min_bodies = 0; // the parallel paths
        world.contact.substeps = 1;            // h |w| = 50 within the step
        std::vector<BodyDef> bodies(1);
        bodies[0].shape = Shape::plane();
        bodies[0].motion = Motion::Static;
        for (int i = 0; i < 600; ++i) {
            BodyDef b;
            b.shape = Shape::box(Vec3(0.1, 0.2, 0.3));
            b.position = Vec3(40.0 * (i % 30), 40.0 * (i / 30), 100.0); // beyond a step's reach
            const bool fast = i + 1 == kFirst || i + 1 == kSecond;
            b.angular_velocity = Vec3(0.001, fast ? 100.0 : 0.01, 0.001);
            bodies.push_back(b);
        }
        model = build_model(world, bodies);
        model.passes.contacts = true; // the stage's threads run the integrator
        state = initial_state(model, bodies);
    }
};

std::optional<DivergenceError> first_error(int threads) {
    Failing f;
    EXPECT_TRUE(f.model.passes.contacts);
    StepWorkspace ws(threads);
    try {
        for (int k = 0; k < 100; ++k) step(f.model, f.state, ws);
    } catch (const DivergenceError& e) {
        return e;
    }
    return std::nullopt;
}

TEST(ParallelIntegrate, AFailureOnAnyWorkerIsTheSingleThreadedError) {
    const std::optional<DivergenceError> one = first_error(1), two = first_error(2);
    ASSERT_TRUE(one.has_value());
    ASSERT_TRUE(two.has_value());
    EXPECT_EQ(one->body, Failing::kFirst);
    EXPECT_EQ(two->body, one->body);
    EXPECT_EQ(two->step, one->step);
    EXPECT_STREQ(two->what(), one->what());
}

} // namespace
} // namespace tumble::physics
