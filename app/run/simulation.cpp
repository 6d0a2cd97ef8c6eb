#include "app/run/simulation.h"

#include "app/scene/scene_check.h"

namespace tumble::app {

Simulation make_simulation(const Scene& scene, double dt, int threads) {
    CheckedStart start = build_checked(scene, dt);
    Simulation sim{
        std::move(start.model), std::move(start.state), nullptr, scene.source, {}, {}, {}};
    for (const BodyLook& look : scene.looks) sim.body_names.push_back(look.name);
    sim.workspace =
        std::make_unique<physics::StepWorkspace>(sim.model.passes.contacts ? threads : 1);
    return sim;
}

void Simulation::step() {
    try {
        physics::step(model, state, *workspace);
        if (model.passes.contacts) effort.add(workspace->contacts.stats());
        if (estimate.estimator) advance_error_estimate(*this);
    } catch (const physics::ShadowDivergenceError& e) {
        throw physics::ShadowDivergenceError(e, e.main_step,
                                             source + ": " + with_body_names(body_names, e.what()));
    } catch (const physics::DivergenceError& e) {
        throw physics::DivergenceError(e.body, e.step, e.quantity,
                                       source + ": " + with_body_names(body_names, e.what()));
    }
}

std::string effort_summary(const Simulation& sim) {
    if (!sim.model.passes.contacts) return "";
    return sim.effort.describe(sim.model.contact, sim.model.dt);
}

std::string threads_note(const Simulation& sim, int threads) {
    if (threads <= 1) return "";
    const std::string asked = "--threads " + std::to_string(threads) + " not used: ";
    const physics::Model& m = sim.model;
    if (!m.passes.contacts)
        return asked + "the scene has no contact stage (" + m.touch.why +
               "), and only contacts run on several threads";
    const auto bodies = static_cast<long long>(m.dynamic_bodies.size());
    if (physics::steps_on_one_thread(m.contact, m.dynamic_bodies.size()))
        return asked + "the scene has " + std::to_string(bodies) +
               (bodies == 1 ? " dynamic body" : " dynamic bodies") +
               ", fewer than world.parallel_min_bodies (" +
               std::to_string(m.contact.parallel_min_bodies) +
               "); one thread is faster there (set it to 0 to use the threads anyway)";
    return "";
}

} // namespace tumble::app
