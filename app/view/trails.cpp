#include "app/view/trails.h"

#include "app/view/body_size.h"
#include "app/view/rod.h"
#include "app/view/to_glm.h"

#include <algorithm>
#include <cmath>

namespace tumble::app {

Trails::Trails(const Scene& scene, const physics::Model& model, const physics::State& initial,
               std::size_t frames, int axis)
    : axis_(axis), capacity_(std::max<std::size_t>(frames, 2)) {
    for (int b : model.dynamic_bodies) {
        bodies_.push_back(b);
        colours_.push_back(scene.looks[std::size_t(b)].color);
        reach_.push_back(float(1.2 * body_size(model, b))); // the axis tip: 1.2 sizes out
    }
    centres_.resize(capacity_ * bodies_.size());
    tips_.resize(axis_ >= 0 ? capacity_ * bodies_.size() : 0);
    record(model, initial);
}

void Trails::record(const physics::Model& model, const physics::State& state) {
    const std::size_t n = bodies_.size();
    for (std::size_t i = 0; i < n; ++i) {
        const int b = bodies_[i];
        centres_[head_ * n + i] = to_glm(state.x[std::size_t(b)]);
        if (axis_ >= 0) {
            const physics::Quat r = physics::body_pose(model, state, b).orientation;
            const physics::Vec3 e = r * physics::Vec3::Unit(axis_);
            tips_[head_ * n + i] = to_glm(state.x[std::size_t(b)] + double(reach_[i]) * e);
        }
    }
    head_ = (head_ + 1) % capacity_;
    count_ = std::min(count_ + 1, capacity_);
}

void Trails::add(render::SceneView& view) const {
    render::Polylines& lines = view.lines;
    const std::size_t n = bodies_.size();
    const std::size_t oldest = (head_ + capacity_ - count_) % capacity_;
    auto strip = [&](const std::vector<glm::vec3>& points, std::size_t i, glm::vec3 colour,
                     float width) {
        lines.begin(width);
        for (std::size_t k = 0; k < count_; ++k) {
            const std::size_t slot = (oldest + k) % capacity_;
            // Opacity rises from 0 at the oldest point to 0.9 at the newest.
            const float age = count_ > 1 ? float(k) / float(count_ - 1) : 1.0f;
            lines.add(points[slot * n + i], glm::vec4(colour, 0.9f * age));
        }
    };
    const std::size_t newest = (head_ + capacity_ - 1) % capacity_;
    for (std::size_t i = 0; i < n; ++i) {
        strip(centres_, i, colours_[i], 3.0f);
        if (axis_ < 0) continue;
        const glm::vec3 colour = glm::mix(colours_[i], glm::vec3(1.0f), 0.5f);
        strip(tips_, i, colour, 2.0f);
        // The traced axis itself, from the centre to the trail's newest point, so the trail
        // hangs from something (with or without --axes).
        view.instances.push_back(
            rod(centres_[newest * n + i], tips_[newest * n + i], 0.025f * reach_[i], colour));
    }
}

} // namespace tumble::app
