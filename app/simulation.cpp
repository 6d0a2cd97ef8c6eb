#include "app/simulation.h"

#include "app/scene_error.h"

namespace tumble::app {

Simulation make_simulation(const Scene& scene, double dt) {
    physics::WorldDef world = scene.world;
    world.dt = dt;
    try {
        Simulation sim{physics::build_model(world, scene.bodies), {}};
        sim.state = physics::initial_state(sim.model, scene.bodies);
        return sim;
    } catch (const physics::ModelError& e) {
        // Shape dimensions live under "shape" in the scene format; the rest match by name.
        const bool in_shape = e.field == "radius" || e.field == "size";
        const std::string field = in_shape ? "shape/" + e.field : e.field;
        const std::string place =
            e.body < 0 ? "/world/" + field : "/bodies/" + std::to_string(e.body) + "/" + field;
        throw SceneError(scene.source, place, e.what());
    }
}

} // namespace tumble::app
