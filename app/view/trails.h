#pragma once
// Trails (--trails): the path of each dynamic body's centre of mass over the last few seconds,
// fading with age, in the body's colour; optionally (--trail-axis x|y|z) also the path of the
// tip of one of its own axes, which shows how it turns (a body axis traces a cone as a top
// precesses; the middle axis of a flipping book swings through half a turn), with that axis
// drawn as a rod out to the tip in the trail's colour, so the trail hangs from it. Sampled at
// every frame time into a ring of fixed size: memory is bodies x frames in the window.
#include "app/scene/scene.h"
#include "physics/model.h"
#include "physics/state.h"
#include "render/scene_view.h"

#include <cstddef>
#include <vector>

namespace tumble::app {

class Trails {
  public:
    // `frames` frames of history (the window times the frame rate, plus one); `axis` 0, 1, 2 or
    // -1 for none. Records the first sample.
    Trails(const Scene& scene, const physics::Model& model, const physics::State& initial,
           std::size_t frames, int axis);
    void record(const physics::Model& model, const physics::State& state);
    // The trails into view.lines and the traced axes' rods into view.instances.
    void add(render::SceneView& view) const;

  private:
    std::vector<int> bodies_;        // the dynamic bodies
    std::vector<glm::vec3> colours_; // per traced body, sRGB
    std::vector<float> reach_;       // per traced body: how far the axis tip is from the centre, m
    int axis_;
    std::size_t capacity_, count_ = 0, head_ = 0; // ring of frames
    std::vector<glm::vec3> centres_, tips_;       // [frame slot][traced body]
};

} // namespace tumble::app
