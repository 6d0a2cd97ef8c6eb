#pragma once
// Shared by the integrator tests: build a reference scene (physics/scenes/reference_scenes.h) with
// a given integrator and step, run it, and measure the distance to the exact solution.
#include "physics/build.h"
#include "physics/exact/body_motion.h"
#include "physics/integrator.h"
#include "physics/scenes/reference_scenes.h"
#include "physics/step.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace tumble::physics::testing {

struct World {
    Model model;
    State state;
};

inline World make_world(const scenes::Scene& scene, Integrator integrator, double h) {
    WorldDef world = scene.world;
    world.integrator = integrator;
    world.dt = h;
    World w{build_model(world, scene.bodies), {}};
    w.state = initial_state(w.model, scene.bodies);
    return w;
}

inline void run(World& w, long steps) {
    for (long k = 0; k < steps; ++k) step(w.model, w.state);
}

// Error of a state against the exact motion at the same time, over all dynamic bodies (the worst):
// rotation angle (rad) + |w - w_exact| / |w_exact| + |x - x_exact| (m) + |v - v_exact| (m/s).
// Each term is O(1) for a body that tumbles and travels a few metres, so the sum converges at the
// order of its slowest term.
inline double error_against_exact(const World& w, const std::vector<exact::ExactBodyMotion>& ex) {
    const double t = w.state.time(w.model);
    double worst = 0.0;
    for (std::size_t j = 0; j < ex.size(); ++j) {
        const int i = w.model.dynamic_bodies[j];
        const exact::BodyState b = ex[j].at(t);
        const double e = rotation_angle_between(w.state.q[i], b.q) +
                         (w.state.w[i] - b.w).norm() / b.w.norm() + (w.state.x[i] - b.x).norm() +
                         (w.state.v[i] - b.v).norm();
        worst = std::max(worst, e);
    }
    return worst;
}

// Runs `scene` with `integrator` at step h up to the scene's duration (rounded to whole steps)
// and returns the error against the exact solution there.
inline double error_at_end(const scenes::Scene& scene, Integrator integrator, double h) {
    World w = make_world(scene, integrator, h);
    std::vector<exact::ExactBodyMotion> ex;
    for (int i : w.model.dynamic_bodies) ex.emplace_back(w.model, w.state, i);
    run(w, std::lround(scene.duration / h));
    return error_against_exact(w, ex);
}

// `scene` as integrator `id` takes it: for one that refuses applied torques (`exact`,
// IntegratorInfo::refuses_torque) the torques are removed; the refusal itself is tested in
// exact_integrator_test.cpp.
inline scenes::Scene as_taken_by(scenes::Scene scene, Integrator id) {
    if (integrator_info(id).refuses_torque)
        for (BodyDef& b : scene.bodies) b.applied_torque = Vec3::Zero();
    return scene;
}

inline bool bit_equal(const State& a, const State& b) {
    const auto same = [](const auto& u, const auto& v) {
        return u.size() == v.size() &&
               std::memcmp(u.data(), v.data(), sizeof(u[0]) * u.size()) == 0;
    };
    return a.step == b.step && same(a.x, b.x) && same(a.q, b.q) && same(a.v, b.v) && same(a.w, b.w);
}

inline std::string name_of(Integrator id) {
    return std::string(integrator_info(id).name);
}

inline std::vector<Integrator> all_integrators() {
    std::vector<Integrator> out;
    for (const IntegratorInfo& info : integrators()) out.push_back(info.id);
    return out;
}

} // namespace tumble::physics::testing
