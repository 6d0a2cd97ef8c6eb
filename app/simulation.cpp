#include "app/simulation.h"

#include "app/scene_error.h"
#include "physics/overlaps.h"

#include <cstdio>
#include <regex>

namespace tumble::app {
namespace {

// Where a physics field lives in the scene format, below /bodies/i or /world.
std::string json_field(const std::string& field) {
    if (field == "radius" || field == "size" || field == "length" || field == "file")
        return "shape/" + field;
    if (field == "friction" || field == "restitution") return "material/" + field;
    return field;
}

std::string body_label(const Scene& scene, int i) {
    return "body " + std::to_string(i) + " \"" + scene.looks[std::size_t(i)].name + "\"";
}

// "body 3" -> "body 3 "left wall"" in physics' messages, so the user sees the names they wrote.
std::string with_body_names(const Scene& scene, const std::string& what) {
    static const std::regex body(R"(\bbody (\d+)\b)");
    std::string out;
    auto last = what.cbegin();
    for (std::sregex_iterator it(what.begin(), what.end(), body), end; it != end; ++it) {
        const int i = std::stoi((*it)[1].str());
        out.append(last, (*it)[0].first);
        out += i >= 0 && i < int(scene.looks.size()) ? body_label(scene, i) : (*it)[0].str();
        last = (*it)[0].second;
    }
    out.append(last, what.cend());
    return out;
}

} // namespace

Simulation make_simulation(const Scene& scene, double dt, int threads) {
    physics::WorldDef world = scene.world;
    world.dt = dt;
    try {
        Simulation sim{physics::build_model(world, scene.bodies), {}, nullptr};
        sim.state = physics::initial_state(sim.model, scene.bodies);
        sim.workspace =
            std::make_unique<physics::StepWorkspace>(sim.model.passes.contacts ? threads : 1);
        return sim;
    } catch (const physics::ModelError& e) {
        const std::string field = json_field(e.field);
        const std::string place =
            e.body < 0 ? "/world/" + field : "/bodies/" + std::to_string(e.body) + "/" + field;
        throw SceneError(scene.source, place, with_body_names(scene, e.what()));
    }
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

std::vector<std::string> initial_state_warnings(const Scene& scene, const Simulation& sim) {
    std::vector<std::string> out;
    if (!sim.model.passes.contacts) return out;
    for (const physics::Overlap& o : physics::deep_initial_overlaps(sim.model, sim.state)) {
        char numbers[96];
        std::snprintf(numbers, sizeof numbers,
                      " by %.1f mm; contacts will push them apart at up "
                      "to %.3g m/s",
                      o.depth * 1000.0, sim.model.contact.max_push_speed);
        out.push_back(scene.source + ": /bodies/" + std::to_string(o.b) +
                      "/position: " + body_label(scene, o.b) + " starts interpenetrating " +
                      body_label(scene, o.a) + numbers + " (move them apart if not intended)");
    }
    return out;
}

} // namespace tumble::app
