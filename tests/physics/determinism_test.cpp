// Same model, same build: bit-identical states. A saved state (a copy) continues bit-identically.
#include "physics/build.h"
#include "physics/step.h"

#include <gtest/gtest.h>

#include <cstring>

namespace tumble::physics {
namespace {

std::vector<BodyDef> tumbling_scene() {
    BodyDef book;
    book.shape = Shape::box(Vec3(0.1, 0.03, 0.15));
    book.mass = 0.6;
    book.angular_velocity = Vec3(0.02, 6.0, 0.02);
    BodyDef ball;
    ball.position = Vec3(1.0, 0.0, 2.0);
    ball.velocity = Vec3(0.5, 0.0, 4.0);
    return {book, ball};
}

bool bit_equal(const State& a, const State& b) {
    auto same = [](const auto& u, const auto& v) {
        return u.size() == v.size() &&
               std::memcmp(u.data(), v.data(), sizeof(u[0]) * u.size()) == 0;
    };
    return a.step == b.step && same(a.x, b.x) && same(a.q, b.q) && same(a.v, b.v) && same(a.w, b.w);
}

TEST(Determinism, TwoRunsAreBitIdentical) {
    const auto bodies = tumbling_scene();
    const Model m = build_model({}, bodies);
    State a = initial_state(m, bodies), b = initial_state(m, bodies);
    for (int k = 0; k < 2000; ++k) step(m, a);
    for (int k = 0; k < 2000; ++k) step(m, b);
    EXPECT_TRUE(bit_equal(a, b));
}

TEST(Determinism, RestoredStateContinuesBitIdentically) {
    const auto bodies = tumbling_scene();
    const Model m = build_model({}, bodies);
    State run = initial_state(m, bodies);
    for (int k = 0; k < 700; ++k) step(m, run);
    const State saved = run;
    for (int k = 0; k < 700; ++k) step(m, run);
    State resumed = saved;
    for (int k = 0; k < 700; ++k) step(m, resumed);
    EXPECT_TRUE(bit_equal(run, resumed));
}

} // namespace
} // namespace tumble::physics
