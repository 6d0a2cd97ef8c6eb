#include "app/view/vector_arrows.h"

#include "app/view/body_size.h"

#include "physics/diagnostics.h"
#include "physics/rigid_body.h"
#include "render/cone_mesh.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace tumble::app {
namespace {

constexpr double kReach = 3.0; // arrow length at the reference magnitude, in body sizes
constexpr double kTwoPi = 6.283185307179586;
constexpr float kShaft = 0.045f;                         // shaft radius, in body sizes
constexpr float kHeadRadius = 0.11f, kHeadLength = 0.3f; // in body sizes
const glm::vec3 kOmegaColor(0.96f, 0.69f, 0.25f);        // amber
const glm::vec3 kMomentumColor(0.09f, 0.65f, 0.78f);     // cyan

// A rotation taking +z to the unit vector d.
glm::mat4 aim_z_at(const glm::vec3& d) {
    const glm::vec3 z(0.0f, 0.0f, 1.0f);
    const glm::vec3 axis = glm::cross(z, d);
    const float s = glm::length(axis), c = glm::dot(z, d);
    if (s < 1e-6f)
        return c > 0.0f ? glm::mat4(1.0f)
                        : glm::rotate(glm::mat4(1.0f), 3.14159265f, glm::vec3(1, 0, 0));
    return glm::rotate(glm::mat4(1.0f), std::atan2(s, c), axis / s);
}

// Shaft (unit cylinder: radius 1, z in [-1, 1]) and head (unit cone: base at z = 0, apex at
// z = 1) of an arrow of `length` metres from `origin` along the unit vector `dir`.
void push_arrow(render::SceneView& view, render::MeshId cone, const glm::vec3& origin,
                const glm::vec3& dir, float length, float size, const glm::vec3& color) {
    const float head = std::min(kHeadLength * size, 0.5f * length);
    const float shaft = length - head;
    const glm::mat4 frame = glm::translate(glm::mat4(1.0f), origin) * aim_z_at(dir);
    render::Instance s;
    s.mesh = render::MeshKind::Cylinder;
    s.transform =
        frame * glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 0.5f * shaft)) *
        glm::scale(glm::mat4(1.0f), glm::vec3(kShaft * size, kShaft * size, 0.5f * shaft));
    s.color = color;
    s.material = render::Material{0.35f, 0.5f, 0.0f};
    render::Instance h = s;
    h.mesh = render::MeshKind::Custom;
    h.mesh_id = cone;
    h.transform =
        frame * glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, shaft)) *
        glm::scale(glm::mat4(1.0f), glm::vec3(kHeadRadius * size, kHeadRadius * size, head));
    view.instances.push_back(s);
    view.instances.push_back(h);
}

glm::vec3 to_glm(const physics::Vec3& v) {
    return glm::vec3(float(v.x()), float(v.y()), float(v.z()));
}

} // namespace

VectorArrows::VectorArrows(const physics::Model& model, const physics::State& initial)
    : scale_(std::size_t(model.body_count()), Scale{0.0, 0.0, 0.0}),
      cone_(std::make_shared<const render::MeshData>(render::make_cone())) {
    for (int i : model.dynamic_bodies) {
        const double i_max = model.inertia[i].maxCoeff();
        const double size = body_size(model, i);
        const double w_ref = std::max(initial.w[i].norm(), kTwoPi);
        const double l_ref =
            std::max(physics::spin_angular_momentum(model, initial, i).norm(), i_max * kTwoPi);
        scale_[std::size_t(i)] = {size, kReach * size / w_ref, kReach * size / l_ref};
    }
}

void VectorArrows::add(const physics::Model& model, const physics::State& state,
                       render::SceneView& view) const {
    const auto cone = render::MeshId(view.meshes.size());
    view.meshes.push_back(cone_);
    for (int i : model.dynamic_bodies) {
        const Scale& sc = scale_[std::size_t(i)];
        const glm::vec3 origin = to_glm(state.x[i]);
        const physics::Vec3 w = state.w[i];
        const physics::Vec3 l = physics::spin_angular_momentum(model, state, i);
        const float size = float(sc.size);
        // An arrow shorter than its own head says nothing: below that it is left out.
        if (const double len = sc.per_w * w.norm(); len > kHeadLength * sc.size)
            push_arrow(view, cone, origin, to_glm(w.normalized()), float(len), size, kOmegaColor);
        if (const double len = sc.per_l * l.norm(); len > kHeadLength * sc.size)
            push_arrow(view, cone, origin, to_glm(l.normalized()), float(len), size,
                       kMomentumColor);
    }
}

const char* VectorArrows::legend() {
    return "arrows: w amber, L = I_w w cyan";
}

} // namespace tumble::app
