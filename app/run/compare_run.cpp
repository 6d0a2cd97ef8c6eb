#include "app/run/compare_run.h"

#include "app/run/auto_camera.h"
#include "app/run/prepare_run.h"
#include "app/run/progress.h"
#include "app/run/render_frames.h"
#include "app/scene/scene_error.h"
#include "io/interrupt.h"

#include <algorithm>

namespace tumble::app {
namespace {

std::vector<physics::Integrator> parse_methods(const std::vector<std::string>& names) {
    std::vector<physics::Integrator> out;
    for (const std::string& name : names) {
        const auto id = physics::integrator_from_name(name);
        if (!id)
            throw SceneError("--compare", name,
                             "unknown integrator; valid integrators: " +
                                 physics::integrator_names());
        if (std::find(out.begin(), out.end(), *id) != out.end())
            throw SceneError("--compare", name, "each integrator may appear once");
        out.push_back(*id);
    }
    if (out.size() < 2 || out.size() > 9)
        throw SceneError("--compare", std::to_string(out.size()) + " integrators",
                         "expected 2 to 9 names separated by commas");
    return out;
}

} // namespace

void check_compare_request(const RunRequest& run) {
    if (run.integrator)
        throw SceneError("--integrator", *run.integrator,
                         "not with --compare, which names the integrators itself");
}

CompareRun render_compare(Scene loaded, RenderRequest request, int threads, bool quiet,
                          const std::function<void(const std::string&)>& note) {
    apply_render_overrides(request, loaded);
    if (!request.overlay) loaded.render.overlay = true; // each tile is labelled by its overlay
    const auto methods = parse_methods(request.compare);
    // The lanes name their integrators: a tolerance is checked for each, not chosen for.
    loaded.accuracy.auto_integrator = false;
    RunPlan plan = plan_run(std::move(loaded));
    Scene& scene = plan.scene;
    const Timeline& tl = plan.timeline;
    if (const std::string n = resolve_time(request, tl); !n.empty()) note(n);
    check_frame_index(request, tl);
    const std::int64_t first = request.frame.value_or(0);
    const std::int64_t last = request.frame.value_or(tl.frames - 1);
    tune_allocator_for_rendering();
    const std::unique_ptr<render::FrameSink> sink =
        open_render_sink(request, scene, output_name(request, scene, "-compare"), {}, quiet);
    frame_automatically(scene, tl, quiet); // camera.auto, once outputs are good
    SideBySide tiles(scene, methods, tl, threads, first, last);
    render::Image frame;
    Progress progress("comparing", last - first + 1, quiet);
    CompareRun out;
    for (std::int64_t k = first; k <= last && !io::InterruptGuard::requested(); ++k) {
        tiles.draw_next(frame);
        sink->write(frame);
        progress.update(++out.frames);
    }
    progress.finish();
    if (out.frames > 0)
        sink->finish();
    else
        sink->abort(); // interrupted before the first frame: nothing worth keeping
    out.lanes = tiles.results();
    out.output = sink->describe();
    out.sink_note = sink->note();
    out.interrupted = io::InterruptGuard::requested();
    out.cols = tiles.cols();
    out.rows = tiles.rows();
    out.tile_width = tiles.tile_width();
    out.tile_height = tiles.tile_height();
    return out;
}

} // namespace tumble::app
