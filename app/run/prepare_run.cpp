#include "app/run/prepare_run.h"

#include "app/run/accuracy_choice.h"
#include "app/run/run_estimate.h"

namespace tumble::app {

RunPlan plan_run(Scene scene) {
    resolve_auto_integrator(scene); // for these frame times: steps land on t = k / fps
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    return {std::move(scene), tl};
}

Simulation start_run(const Scene& scene, const Timeline& timeline, const RunOptions& options) {
    Simulation sim = make_simulation(scene, timeline.h, options.threads);
    if (options.error_estimate) start_error_estimate(sim, scene, options.threads);
    return sim;
}

PreparedRun prepare_run(Scene scene, const RunOptions& options) {
    RunPlan plan = plan_run(std::move(scene));
    Simulation sim = start_run(plan.scene, plan.timeline, options);
    return {std::move(plan.scene), plan.timeline, std::move(sim)};
}

std::vector<std::string> PreparedRun::notes(int threads) const {
    std::vector<std::string> out;
    for (const std::string& note : {timeline.adjustment_note(), threads_note(sim, threads)})
        if (!note.empty()) out.push_back(note);
    return out;
}

} // namespace tumble::app
