#pragma once
// Arrows for teaching (render.vectors / --vectors): at each dynamic body's centre of mass, its
// angular velocity w (amber) and its spin angular momentum L = I_w w = R I_body R^T w (magenta,
// apart from the body axes' red, green and blue), both in the world frame. In torque-free motion
// L stays fixed in space while w wanders around it: the intermediate-axis flip shows w swinging
// through the body while L never moves.
//
// Lengths are proportional to the magnitudes, with one scale per body and quantity fixed at
// t = 0 (so growth and decay show): w's arrow is 3 body sizes long at its reference magnitude
// w_ref = max(|w(0)|, 2 pi rad/s), L's 4 (and thinner) at L_ref = max(|L(0)|, I_max 2 pi rad/s),
// so that when the two nearly line up (a spinning plate) L's head still shows beyond w's; a
// body's size is 1.7 sqrt(I_max / m), about its radius for a sphere and its half-diagonal for a
// box.
#include "app/scene/scene.h"
#include "app/view/overlay_layout.h"
#include "physics/model.h"
#include "physics/state.h"
#include "render/mesh_data.h"
#include "render/scene_view.h"

#include <memory>
#include <vector>

namespace tumble::app {

class VectorArrows {
  public:
    // Fixes the scales from the state at t = 0.
    VectorArrows(const physics::Model& model, const physics::State& initial);

    // Appends the arrows' instances (a cylinder shaft and a cone head each) to `view`, and the
    // cone to view.meshes.
    void add(const physics::Model& model, const physics::State& state,
             render::SceneView& view) const;

    // What the colours are, for the frame's legend (shorter names when `compact`).
    static std::vector<LegendItem> legend(bool compact);

  private:
    struct Scale {
        double size;  // m
        double per_w; // m per rad/s
        double per_l; // m per kg m^2/s
    };
    std::vector<Scale> scale_; // per body; size 0 for static bodies
    std::shared_ptr<const render::MeshData> cone_;
};

} // namespace tumble::app
