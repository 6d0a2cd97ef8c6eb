// The camera rig (app/scene/camera_rig.h) evaluated at a frame's time.
#include "app/view/camera.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace tumble::app {
namespace {

glm::vec3 to_float(const glm::dvec3& v) {
    return glm::vec3(v);
}

// Cubic Hermite between keys i and i+1 at parameter s in [0, 1], with Catmull-Rom tangents
// (central differences over the neighbouring keys, scaled to the segment's duration) and zero
// tangents at the two ends, so the camera eases in and out of the path.
template <class T, class Get>
T hermite(const std::vector<CameraKey>& keys, std::size_t i, double s, Get get) {
    const std::size_t n = keys.size();
    const double dt = keys[i + 1].t - keys[i].t;
    auto tangent = [&](std::size_t k) -> T {
        if (k == 0 || k + 1 == n) return T(0.0);
        return (get(keys[k + 1]) - get(keys[k - 1])) * (dt / (keys[k + 1].t - keys[k - 1].t));
    };
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * get(keys[i]) + (s3 - 2 * s2 + s) * tangent(i) +
           (-2 * s3 + 3 * s2) * get(keys[i + 1]) + (s3 - s2) * tangent(i + 1);
}

render::Camera on_path(const CameraRig& rig, double t) {
    render::Camera c = rig.base;
    const auto& k = rig.keys;
    std::size_t i = 0;
    while (i + 2 < k.size() && t >= k[i + 1].t) ++i;
    const double s = std::clamp((t - k[i].t) / (k[i + 1].t - k[i].t), 0.0, 1.0);
    c.position =
        to_float(hermite<glm::dvec3>(k, i, s, [](const CameraKey& q) { return q.position; }));
    c.target = to_float(hermite<glm::dvec3>(k, i, s, [](const CameraKey& q) { return q.target; }));
    c.fov_y_deg = float(hermite<double>(k, i, s, [](const CameraKey& q) { return q.fov_deg; }));
    return c;
}

} // namespace

render::Camera camera_at(const CameraRig& rig, double t, const glm::dvec3& body) {
    render::Camera c = rig.base;
    switch (rig.mode) {
    case CameraRig::Mode::Fixed:
    case CameraRig::Mode::Auto: // not yet framed (app/run/auto_camera.h): the base camera
    case CameraRig::Mode::Poinsot:
        break;
    case CameraRig::Mode::Orbit: {
        const double a = rig.start_angle + glm::two_pi<double>() * t / rig.period;
        c.target = to_float(rig.center);
        c.position = to_float(rig.center + glm::dvec3(rig.radius * std::cos(a),
                                                      rig.radius * std::sin(a), rig.height));
        break;
    }
    case CameraRig::Mode::Follow:
        c.target = to_float(body);
        if (!rig.track) c.position = to_float(body + rig.offset);
        break;
    case CameraRig::Mode::Path:
        c = on_path(rig, t);
        break;
    }
    return c;
}

} // namespace tumble::app
