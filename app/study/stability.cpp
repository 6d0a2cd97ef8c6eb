#include "app/study/stability.h"
#include "app/study/boundary_search.h"
#include "app/study/runner.h"
#include "physics/build.h"
#include "physics/integrator.h"
#include "physics/step.h"

#include <cmath>

namespace tumble::app::study {

using physics::Vec3;

std::vector<InertiaCase> stability_cases(bool quick) {
    std::vector<InertiaCase> cases{{"sphere", 1.0, Vec3(1.0, 1.0, 1.0)}};
    const std::vector<double> ks = quick ? std::vector<double>{1e1, 1e3, 1e6}
                                         : std::vector<double>{1e1, 1e2, 1e3, 1e4, 1e5, 1e6};
    for (double k : ks) cases.push_back({"plate", k, Vec3(1.0, k, 1.0 + k)});
    for (double k : ks) cases.push_back({"rod", k, Vec3(1.0 / k, 1.0, 1.0)});
    return cases;
}

bool keeps_energy(const std::string& integrator, const Vec3& moments, double h_w) {
    physics::WorldDef world;
    world.gravity = Vec3::Zero();
    world.integrator = physics::integrator_from_name(integrator).value();
    world.dt = h_w; // |w| = 1 rad/s
    physics::BodyDef body;
    body.shape = physics::Shape::box(Vec3(0.1, 0.1, 0.1));
    body.inertia = moments.asDiagonal();
    body.angular_velocity = Vec3(1.0, 1.0, 1.0).normalized();
    const physics::Model model = physics::build_model(world, {body});
    physics::State state = physics::initial_state(model, {body});
    // T_rot = 1/2 w_b . I w_b with w_b = R^T w in the principal axes (diagnostics.h).
    const auto energy = [&] {
        const Vec3 wb = state.q[0].conjugate() * state.w[0];
        return 0.5 * wb.dot(model.inertia[0].cwiseProduct(wb));
    };
    const double e0 = energy();
    try {
        for (int k = 0; k < kStabilitySteps; ++k) {
            physics::step(model, state);
            if (!(std::abs(energy() - e0) <= kStabilityEnergyTolerance * e0)) return false;
        }
    } catch (const physics::DivergenceError&) {
        return false;
    }
    return true;
}

namespace {

StabilityResult search(const InertiaCase& c, const std::string& integrator, double ratio) {
    StabilityResult r{c, integrator, kMinHw, false, false, 0};
    const Boundary b = largest_passing(kMinHw, kMinHw, kMaxHw, ratio, [&](double h_w) {
        ++r.evaluations;
        return keeps_energy(integrator, c.moments, h_w);
    });
    r.h_w = b.value;
    r.below_range = b.below_range;
    r.above_range = b.above_range;
    return r;
}

} // namespace

std::vector<StabilityResult> stability_map(bool quick, int threads) {
    const std::vector<InertiaCase> cases = stability_cases(quick);
    std::vector<std::string> names;
    for (const physics::IntegratorInfo& info : physics::integrators())
        names.emplace_back(info.name);
    std::vector<StabilityResult> out(cases.size() * names.size());
    parallel_for(static_cast<int>(out.size()), threads, [&](int i) {
        out[i] = search(cases[i / names.size()], names[i % names.size()], quick ? 1.05 : 1.01);
    });
    return out;
}

} // namespace tumble::app::study
