#include "app/run/auto_camera.h"

#include "app/run/prepare_run.h"
#include "app/run/progress.h"
#include "app/run/simulation.h"
#include "app/run/swept_spheres.h"
#include "app/view/poinsot.h"
#include "app/view/vector_arrows.h"
#include "io/interrupt.h"
#include "physics/can_touch.h"
#include "physics/model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace tumble::app {
namespace {

using physics::kInf;

glm::dvec3 to_d(const physics::Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

// The scene's up axis: against gravity, or the rig's own up when there is no gravity.
glm::dvec3 up_axis(const Scene& scene) {
    const physics::Vec3 g = scene.world.gravity;
    if (g.norm() > 0.0) return -to_d(g) / g.norm();
    return glm::normalize(glm::dvec3(scene.render.camera.base.up));
}

using Sample = SweptSample; // a sphere that must be in frame

// The camera basis: d towards the camera, r to the right, u up on screen; and the half-frame
// tangents with the margin taken off.
struct Basis {
    glm::dvec3 d, r, u;
    double tan_h, tan_v;
    ViewAxes axes() const { return {r, u, d}; }
    Basis(const glm::dvec3& direction, const glm::dvec3& up, double fov_y_deg, double aspect,
          double margin)
        : d(glm::normalize(direction)), r(glm::normalize(glm::cross(up, d))), u(glm::cross(d, r)),
          tan_h(0), tan_v(std::tan(0.5 * glm::radians(fov_y_deg)) / (1.0 + margin)) {
        tan_h = tan_v * aspect;
    }
};

// The nearest distance from the target c along d at which every sample is in frame: a sphere
// (x, R) with q = x - c is when (|q.r| + R) / (D - q.d - R) <= tan_h, and the same for u.
double fit_distance(const Basis& b, const glm::dvec3& c, const std::vector<Sample>& samples) {
    double distance = 0.1; // a single resting point still gets some room
    for (const Sample& s : samples) {
        const glm::dvec3 q = s.x - c;
        const double reach = glm::dot(q, b.d) + s.radius;
        distance = std::max({distance, reach + (std::abs(glm::dot(q, b.r)) + s.radius) / b.tan_h,
                             reach + (std::abs(glm::dot(q, b.u)) + s.radius) / b.tan_v});
    }
    return distance;
}

// Target and distance: start from the middle of the centres' box [lo, hi], then move the target
// across the view until the samples' extent on screen is centred (perspective makes the near
// side look larger), standing back each time just as far as needed. Four rounds centre it to
// well under a percent of the frame.
render::Camera fit(const Basis& b, const glm::dvec3& up, const std::vector<Sample>& samples,
                   const glm::dvec3& lo, const glm::dvec3& hi) {
    glm::dvec3 c = 0.5 * (lo + hi);
    double distance = fit_distance(b, c, samples);
    for (int round = 0; round < 4; ++round) {
        double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
        for (const Sample& s : samples) {
            const glm::dvec3 q = s.x - c;
            const double depth = std::max(distance - glm::dot(q, b.d), 1e-9);
            const double x = glm::dot(q, b.r) / depth, y = glm::dot(q, b.u) / depth;
            const double rr = s.radius / depth;
            x0 = std::min(x0, x - rr), x1 = std::max(x1, x + rr);
            y0 = std::min(y0, y - rr), y1 = std::max(y1, y + rr);
        }
        c += distance * (0.5 * (x0 + x1) * b.r + 0.5 * (y0 + y1) * b.u);
        distance = fit_distance(b, c, samples);
    }
    render::Camera cam;
    cam.target = glm::vec3(c);
    cam.position = glm::vec3(c + distance * b.d);
    cam.up = glm::vec3(up);
    cam.z_near = static_cast<float>(std::max(0.01, 0.02 * distance));
    cam.z_far = static_cast<float>(std::max(200.0, 4.0 * (distance + glm::length(hi - lo))));
    return cam;
}

// Mode::Poinsot: the construction of render.poinsot at t = 0 (and the arrows, when drawn),
// looked down on from the side the rig's base camera looks from, with a third of the half-frame
// left around it for the overlays' panels.
void frame_poinsot(Scene& scene, const Timeline& tl) {
    CameraRig& rig = scene.render.camera;
    const Simulation sim = start_run(scene, tl, {1, false}); // the state at t = 0
    const glm::dvec3 hint = glm::dvec3(rig.base.position) - glm::dvec3(rig.base.target);
    const PoinsotFraming f =
        poinsot_framing(sim.model, sim.state, scene.render.poinsot.index, hint);
    std::vector<Sample> samples;
    for (const glm::dvec3& p : f.points) samples.push_back({p, 0.0});
    if (scene.render.vectors) { // the arrows' shafts and heads, each by its bounding sphere
        render::SceneView arrows;
        VectorArrows(sim.model, sim.state).add(sim.model, sim.state, arrows);
        for (const render::Instance& in : arrows.instances) {
            const glm::mat4& t = in.transform;
            const double r = std::sqrt(2.0) *
                             std::max({glm::length(glm::vec3(t[0])), glm::length(glm::vec3(t[1])),
                                       glm::length(glm::vec3(t[2]))});
            samples.push_back({glm::dvec3(t[3]), r});
        }
    }
    const double aspect = double(scene.render.width) / double(scene.render.height);
    const float fov = rig.base.fov_y_deg;
    const double margin = std::max(rig.auto_margin, 0.33);
    glm::dvec3 lo(kInf), hi(-kInf); // the centres' box, where the fit starts
    for (const Sample& s : samples) lo = glm::min(lo, s.x), hi = glm::max(hi, s.x);
    rig.base = fit(Basis(f.direction, f.up, fov, aspect, margin), f.up, samples, lo, hi);
    rig.base.fov_y_deg = fov;
    rig.mode = CameraRig::Mode::Fixed;
}

} // namespace

render::Camera frame_box(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& direction,
                         const glm::dvec3& up, double fov_y_deg, double aspect, double margin) {
    std::vector<Sample> corners;
    for (int k = 0; k < 8; ++k)
        corners.push_back(
            {glm::dvec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z), 0.0});
    render::Camera cam = fit(Basis(direction, up, fov_y_deg, aspect, margin), up, corners, lo, hi);
    cam.fov_y_deg = static_cast<float>(fov_y_deg);
    return cam;
}

void frame_automatically(Scene& scene, const Timeline& tl, bool quiet) {
    CameraRig& rig = scene.render.camera;
    if (rig.mode == CameraRig::Mode::Poinsot && scene.render.poinsot.index >= 0)
        return frame_poinsot(scene, tl);
    if (rig.mode == CameraRig::Mode::Poinsot) rig.mode = CameraRig::Mode::Auto; // no construction
    if (rig.mode != CameraRig::Mode::Auto) return;
    const glm::dvec3 up = up_axis(scene);
    glm::dvec3 direction = rig.auto_direction;
    if (glm::length(direction) == 0.0)
        direction = glm::dvec3(rig.base.position) - glm::dvec3(rig.base.target);
    if (glm::length(glm::cross(glm::normalize(direction), up)) < 1e-6)
        direction += 0.5 * glm::dvec3(up.y, up.z, up.x); // looking straight along up: tilt it
    const double aspect = double(scene.render.width) / double(scene.render.height);
    const float fov = rig.base.fov_y_deg;
    const Basis basis(direction, up, fov, aspect, rig.auto_margin);
    // Every body's bounding sphere at every frame, in memory bounded whatever the duration
    // (swept_spheres.h); stopped by Ctrl-C within a frame.
    Simulation sim = start_run(scene, tl, {1, false}); // the run's own steps, no estimate
    const physics::Model& m = sim.model;
    SweptSpheres swept(basis.axes());
    Progress progress("framing the camera", tl.frames, quiet);
    for (std::int64_t k = 0; k < tl.frames; ++k) {
        io::InterruptGuard::stop_if_requested("camera.auto's pre-pass");
        if (k > 0)
            for (int s = 0; s < tl.steps_per_frame; ++s) sim.step();
        for (int i : m.dynamic_bodies) {
            const physics::Vec3& p = sim.state.x[i];
            swept.add(glm::dvec3(p.x(), p.y(), p.z()), physics::bounding_radius(m, i));
        }
        progress.update(k + 1);
    }
    progress.finish();
    if (swept.empty()) swept.add(glm::dvec3(rig.base.target), 0.0); // nothing moves
    rig.base = fit(basis, up, swept.samples(), swept.lo(), swept.hi());
    if (swept.boxed() && !quiet)
        std::fprintf(stderr, "tumble: note: camera.auto: the bodies' paths have too many extreme "
                             "points to keep; framed the box around all of them instead\n");
    rig.base.fov_y_deg = fov;
    rig.mode = CameraRig::Mode::Fixed;
}

} // namespace tumble::app
