#include "app/view/vector_arrows.h"

#include "app/view/body_size.h"
#include "app/view/rod.h"
#include "app/view/to_glm.h"

#include "physics/diagnostics.h"
#include "physics/rigid_body.h"
#include "render/cone_mesh.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace tumble::app {
namespace {

constexpr double kOmegaReach = 3.0, kMomentumReach = 4.0; // at the reference, in body sizes
constexpr double kTwoPi = 6.283185307179586;
constexpr float kHeadRadius = 0.11f, kHeadLength = 0.3f;      // in body sizes
constexpr float kOmegaShaft = 0.045f, kMomentumShaft = 0.03f; // shaft radii, in body sizes
const glm::vec3 kOmegaColor(0.96f, 0.69f, 0.25f);             // amber
const glm::vec3 kMomentumColor(0.86f, 0.24f, 0.78f); // magenta: apart from the axes' red, green
                                                     // and blue, and from blue and cyan bodies

// Shaft (unit cylinder) and head (unit cone: base at z = 0, apex at z = 1) of an arrow of
// `length` metres from `origin` along the unit vector `dir`.
void push_arrow(render::SceneView& view, render::MeshId cone, const glm::vec3& origin,
                const glm::vec3& dir, float length, float size, float shaft_radius,
                const glm::vec3& color) {
    const float head = std::min(kHeadLength * size, 0.5f * length);
    const float shaft = length - head;
    render::Instance h = rod(origin, origin + shaft * dir, shaft_radius * size, color);
    view.instances.push_back(h);
    h.mesh = render::MeshKind::Custom;
    h.mesh_id = cone;
    h.transform =
        glm::translate(glm::mat4(1.0f), origin) * aim_z_at(dir) *
        glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, shaft)) *
        glm::scale(glm::mat4(1.0f), glm::vec3(kHeadRadius * size, kHeadRadius * size, head));
    view.instances.push_back(h);
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
        scale_[std::size_t(i)] = {size, kOmegaReach * size / w_ref, kMomentumReach * size / l_ref};
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
            push_arrow(view, cone, origin, to_glm(w.normalized()), float(len), size, kOmegaShaft,
                       kOmegaColor);
        if (const double len = sc.per_l * l.norm(); len > kHeadLength * sc.size)
            push_arrow(view, cone, origin, to_glm(l.normalized()), float(len), size, kMomentumShaft,
                       kMomentumColor);
    }
}

std::vector<LegendItem> VectorArrows::legend(bool compact) {
    return {{glm::vec4(kOmegaColor, 1.0f), compact ? "w" : "w: angular velocity"},
            {glm::vec4(kMomentumColor, 1.0f), compact ? "L" : "L = I_w w: angular momentum"}};
}

} // namespace tumble::app
