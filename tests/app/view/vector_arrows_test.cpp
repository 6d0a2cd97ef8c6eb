// The teaching arrows (app/view/vector_arrows.h): for a torque-free tumbling book the angular
// momentum arrow must stay fixed in space while the angular velocity arrow wanders, and lengths
// must follow the magnitudes.
#include "app/view/vector_arrows.h"

#include "physics/build.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::app {
namespace {

struct Arrow {
    glm::vec3 dir; // unit
    float length;  // shaft + head, m
};

// The arrows of one body from the instances VectorArrows::add() appends: shaft (cylinder) then
// head (cone), first w then L.
std::vector<Arrow> arrows_in(const render::SceneView& view) {
    std::vector<Arrow> out;
    for (std::size_t i = 0; i + 1 < view.instances.size(); i += 2) {
        const glm::mat4& shaft = view.instances[i].transform;
        const glm::mat4& head = view.instances[i + 1].transform;
        EXPECT_EQ(view.instances[i].mesh, render::MeshKind::Cylinder);
        EXPECT_EQ(view.instances[i + 1].mesh, render::MeshKind::Custom);
        const glm::vec3 axis(shaft[2]); // the unit cylinder's z axis, scaled by half the shaft
        const glm::vec3 tip = glm::vec3(head[3]) + glm::vec3(head[2]); // cone apex at z = 1
        out.push_back({glm::normalize(axis), glm::length(tip - glm::vec3(shaft[3]) + axis)});
    }
    return out;
}

TEST(VectorArrows, MomentumStaysFixedWhileAngularVelocityWanders) {
    physics::WorldDef world;
    world.gravity = physics::Vec3::Zero();
    world.integrator = physics::Integrator::Rk4;
    world.dt = 1.0 / 240.0;
    physics::BodyDef book;
    book.shape = physics::Shape::box(physics::Vec3(0.15, 0.1, 0.02));
    book.angular_velocity = physics::Vec3(0.02, 6.0, 0.02); // about the middle axis: it flips
    const physics::Model model = physics::build_model(world, {book});
    physics::State state = physics::initial_state(model, {book});
    const VectorArrows arrows(model, state);

    render::SceneView view;
    arrows.add(model, state, view);
    ASSERT_EQ(view.instances.size(), 4u);
    const std::vector<Arrow> a0 = arrows_in(view);
    double max_l_turn = 0.0, max_w_turn = 0.0, max_l_stretch = 0.0;
    for (int k = 0; k < 240 * 6; ++k) { // 6 s: through the first flip
        physics::step(model, state);
        view.instances.clear();
        view.meshes.clear();
        arrows.add(model, state, view);
        if (view.instances.size() != 4u) continue; // w may be too short to draw for a moment
        const std::vector<Arrow> a = arrows_in(view);
        max_w_turn = std::max(
            max_w_turn, double(std::acos(std::clamp(glm::dot(a[0].dir, a0[0].dir), -1.0f, 1.0f))));
        max_l_turn = std::max(max_l_turn, double(glm::length(a[1].dir - a0[1].dir)));
        max_l_stretch =
            std::max(max_l_stretch, double(std::abs(a[1].length / a0[1].length - 1.0f)));
    }
    // L is conserved to ~1e-9 by rk4 here; the arrows are single precision (glm).
    TUMBLE_MEASURED(max_l_turn, 1e-5);
    EXPECT_LT(max_l_turn, 1e-5);
    TUMBLE_MEASURED(max_l_stretch, 1e-5);
    EXPECT_LT(max_l_stretch, 1e-5);
    // w swings away from L in the world during the flip (radians; the book's moments set how far)
    TUMBLE_MEASURED(max_w_turn, 0.3);
    EXPECT_GT(max_w_turn, 0.3);
}

TEST(VectorArrows, LengthsFollowMagnitudes) {
    physics::WorldDef world;
    world.gravity = physics::Vec3::Zero();
    physics::BodyDef slow, fast;
    slow.shape = fast.shape = physics::Shape::sphere(0.2);
    slow.position = physics::Vec3(-1, 0, 0);
    fast.position = physics::Vec3(1, 0, 0);
    slow.angular_velocity = physics::Vec3(0, 0, 20.0);
    fast.angular_velocity = physics::Vec3(0, 0, 40.0);
    const physics::Model model = physics::build_model(world, {slow, fast});
    physics::State state = physics::initial_state(model, {slow, fast});
    const VectorArrows arrows(model, state);
    // Both at their own reference magnitude at t = 0: equal lengths, 3 body sizes each.
    render::SceneView view;
    arrows.add(model, state, view);
    ASSERT_EQ(view.instances.size(), 8u);
    std::vector<Arrow> a = arrows_in(view);
    const float size = 1.7f * std::sqrt(0.4f) * 0.2f;
    EXPECT_NEAR(a[0].length, 3.0f * size, 1e-5f);
    EXPECT_NEAR(a[2].length, 3.0f * size, 1e-5f);
    // Halve the fast one's spin: its arrows halve.
    state.w[1] *= 0.5;
    view.instances.clear();
    arrows.add(model, state, view);
    a = arrows_in(view);
    EXPECT_NEAR(a[2].length / a[0].length, 0.5f, 1e-5f);
    EXPECT_NEAR(a[3].length / a[1].length, 0.5f, 1e-5f);
}

} // namespace
} // namespace tumble::app
