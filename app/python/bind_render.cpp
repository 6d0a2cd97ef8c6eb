// render(): frames into a NumPy array, or any output the command line takes. Both prepare the run
// as `tumble render` does (app/run/prepare_run.h, the picture overrides of render_request.h,
// camera.auto's pre-pass) and draw through the same pipeline (app/run/render_frames.h), so frame k
// is the picture of `tumble render --frame k`, bit for bit.
#include "app/python/array_sink.h"
#include "app/python/bindings.h"
#include "app/python/call_scope.h"
#include "app/python/requests.h"

#include "app/run/auto_camera.h"
#include "app/run/compare_run.h"
#include "app/run/prepare_run.h"
#include "app/run/render_frames.h"
#include "app/scene/scene_error.h"
#include "io/bad_input.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>

namespace tumble::python {
namespace py = pybind11;

namespace {

// The frames asked for: `frames` (any order, repeats allowed), or frame= / time= (one still), or
// every frame of the run. Throws SceneError naming the bad index.
std::vector<std::int64_t> wanted_frames(const py::object& frames, app::RenderRequest& req,
                                        const app::Timeline& tl, bool& single) {
    single = false;
    if (!frames.is_none()) {
        if (req.frame || req.time)
            throw io::BadInput("frames= and frame= (or time=): give one or the other");
        std::vector<std::int64_t> out;
        for (const py::handle f : frames) {
            const std::int64_t k =
                py::int_(py::reinterpret_borrow<py::object>(f)).cast<std::int64_t>();
            if (k < 0 || k >= tl.frames)
                throw app::SceneError("frames", std::to_string(k),
                                      "expected a frame index in [0, " +
                                          std::to_string(tl.frames - 1) + "]");
            out.push_back(k);
        }
        if (out.empty()) throw io::BadInput("frames=[]: expected at least one frame index");
        return out;
    }
    app::resolve_time(req, tl);
    app::check_frame_index(req, tl);
    if (req.frame) {
        single = true;
        return {*req.frame};
    }
    std::vector<std::int64_t> all(std::size_t(tl.frames));
    for (std::int64_t k = 0; k < tl.frames; ++k) all[std::size_t(k)] = k;
    return all;
}

py::object render_frames(const py::handle& scene_arg, const py::object& frames, const py::dict& run,
                         const py::dict& picture, int threads, bool progress) {
    app::Scene scene = scene_argument(scene_arg);
    const app::RunRequest run_req = run_request(run);
    app::RenderRequest req = render_request(picture);
    if (!req.compare.empty())
        throw io::BadInput("compare= draws a side-by-side video: give output= as well");
    CallScope scope;
    app::PreparedRun prepared = scope.released([&] {
        app::apply_request(scene, run_req);
        app::apply_render_overrides(req, scene);
        return app::prepare_run(std::move(scene), {threads});
    });
    bool single = false;
    const std::vector<std::int64_t> asked = wanted_frames(frames, req, prepared.timeline, single);
    std::vector<std::int64_t> drawn = asked;
    std::sort(drawn.begin(), drawn.end());
    drawn.erase(std::unique(drawn.begin(), drawn.end()), drawn.end());
    const int w = prepared.scene.render.width, h = prepared.scene.render.height;
    py::array_t<std::uint8_t> out(
        {py::ssize_t(drawn.size()), py::ssize_t(h), py::ssize_t(w), py::ssize_t(3)});
    ArraySink sink(out.mutable_data(), w, h, std::int64_t(drawn.size()));
    const app::RunResult r = scope.released([&] {
        app::frame_automatically(prepared.scene, prepared.timeline, !progress);
        return app::render_frames(prepared.scene, prepared.timeline, prepared.sim, sink, drawn,
                                  !progress);
    });
    if (r.interrupted || scope.interrupted())
        scope.raise_interrupt("interrupted after " + std::to_string(r.frames) + " of " +
                              std::to_string(drawn.size()) + " frames");
    if (single) return out[py::int_(0)];
    if (drawn == asked) return out;
    std::vector<std::int64_t> at; // where each asked frame lies among the drawn ones
    for (std::int64_t k : asked)
        at.push_back(std::lower_bound(drawn.begin(), drawn.end(), k) - drawn.begin());
    return out.attr("take")(py::cast(at), 0);
}

// A run into request.output, as `tumble render -o OUTPUT` (without a shard's tag: a video from
// Python is not a shard for `tumble join`).
py::dict render_output(const py::handle& scene_arg, const py::dict& run, const py::dict& picture,
                       int threads, bool progress) {
    const app::RunRequest run_req = run_request(run);
    app::RenderRequest req = render_request(picture);
    if (!req.compare.empty()) app::check_compare_request(run_req);
    app::Scene scene = scene_argument(scene_arg);
    std::vector<std::string> notes;
    const auto note = [&notes](const std::string& n) { notes.push_back(n); };
    CallScope scope;
    py::dict result;
    if (!req.compare.empty()) {
        const app::CompareRun r = scope.released([&] {
            app::apply_request(scene, run_req);
            return app::render_compare(std::move(scene), req, threads, !progress, note);
        });
        result["output"] = r.output;
        result["frames"] = r.frames;
        result["interrupted"] = r.interrupted;
        std::vector<std::string> lanes;
        for (const app::SideBySide::LaneResult& lane : r.lanes)
            if (!lane.diverged.empty())
                lanes.push_back(lane.integrator + " diverged: " + lane.diverged);
        result["diverged"] = lanes;
    } else {
        const auto [output, frames, interrupted] = scope.released([&] {
            app::apply_request(scene, run_req);
            app::apply_render_overrides(req, scene);
            app::PreparedRun p = app::prepare_run(std::move(scene), {threads});
            if (const std::string n = app::resolve_time(req, p.timeline); !n.empty()) note(n);
            app::check_frame_index(req, p.timeline);
            const std::string name = app::output_name(req, p.scene);
            for (const std::string& n : p.notes(threads)) note(n);
            const std::int64_t first = req.frame.value_or(0);
            const std::int64_t last = req.frame.value_or(p.timeline.frames - 1);
            auto sink = app::open_render_sink(req, p.scene, name, {}, !progress);
            app::frame_automatically(p.scene, p.timeline, !progress);
            const app::RunResult r =
                app::render_frames(p.scene, p.timeline, p.sim, *sink, first, last, !progress);
            if (r.frames > 0)
                sink->finish();
            else
                sink->abort(); // interrupted before the first frame: nothing worth keeping
            return std::tuple(sink->describe(), r.frames, r.interrupted);
        });
        result["output"] = output;
        result["frames"] = frames;
        result["interrupted"] = interrupted;
        result["diverged"] = std::vector<std::string>{};
    }
    result["notes"] = notes;
    if (result["interrupted"].cast<bool>()) {
        const auto frames = result["frames"].cast<std::int64_t>();
        scope.raise_interrupt(frames == 0 ? std::string("interrupted before the first frame; "
                                                        "nothing was written")
                                          : "interrupted after " + std::to_string(frames) +
                                                " frames; " + result["output"].cast<std::string>() +
                                                " is complete and plays");
    }
    return result;
}

} // namespace

void bind_render(py::module_& m) {
    m.def("_render_frames", &render_frames, py::arg("scene"), py::arg("frames"), py::arg("run"),
          py::arg("picture"), py::arg("threads"), py::arg("progress"));
    m.def("_render_output", &render_output, py::arg("scene"), py::arg("run"), py::arg("picture"),
          py::arg("threads"), py::arg("progress"));
}

} // namespace tumble::python
