#include "app/python/requests.h"

#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace tumble::python {
namespace py = pybind11;

namespace {

PyObject* g_warning = nullptr;

// The value of key `name`, or nothing for a missing key or None.
template <class T>
std::optional<T> get(const py::dict& d, const char* name) {
    if (!d.contains(name) || d[name].is_none()) return std::nullopt;
    try {
        return d[name].cast<T>();
    } catch (const py::cast_error&) {
        throw py::type_error(std::string(name) + "=" + py::repr(d[name]).cast<std::string>() +
                             ": expected " + py::type_id<T>());
    }
}

// A number as Python writes it (the shortest text that reads back as the same double): what the
// command line's parsers then read, and what their messages quote.
std::string number_text(const py::handle& value) {
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
}

std::string joined_numbers(const py::handle& values) {
    std::string out;
    for (const py::handle v : values) {
        if (!out.empty()) out += ',';
        out += number_text(v);
    }
    return out;
}

void apply_error_estimate(const py::dict& d, app::RunRequest& r) {
    if (!d.contains("error_estimate") || d["error_estimate"].is_none()) return;
    const py::object e = d["error_estimate"];
    if (py::isinstance<py::bool_>(e)) {
        if (e.cast<bool>())
            r.error_estimate = app::kEstimateOn;
        else
            r.no_error_estimate = true;
    } else if (py::isinstance<py::str>(e)) {
        r.error_estimate = e.cast<std::string>();
    } else {
        r.error_estimate = joined_numbers(e);
    }
}

} // namespace

void set_warning_category(py::handle category) {
    g_warning = category.ptr();
}

void warn(const std::string& text) {
    if (PyErr_WarnEx(g_warning ? g_warning : PyExc_UserWarning, text.c_str(), 1) != 0)
        throw py::error_already_set(); // warnings turned into errors
}

app::Scene load_argument(const py::handle& argument) {
    app::Scene scene;
    if (py::isinstance<py::dict>(argument)) {
        const std::string text =
            py::module_::import("json").attr("dumps")(argument).cast<std::string>();
        scene = app::load_scene(text, "<dict>");
    } else if (py::isinstance<py::str>(argument) || py::hasattr(argument, "__fspath__")) {
        const std::string name =
            py::module_::import("os").attr("fspath")(argument).cast<std::string>();
        scene = app::load_scene_argument(name);
    } else {
        throw py::type_error("expected a scene: a tumble.Scene, a built-in scene's name, a file's "
                             "path or a dict in the scene format, got " +
                             py::repr(py::type::handle_of(argument)).cast<std::string>());
    }
    for (const std::string& w : scene.warnings) warn(w);
    return scene;
}

app::Scene scene_argument(const py::handle& argument) {
    if (py::isinstance<app::Scene>(argument)) return argument.cast<app::Scene>();
    return load_argument(argument);
}

app::RunRequest run_request(const py::dict& d) {
    app::RunRequest r;
    r.integrator = get<std::string>(d, "integrator");
    if (d.contains("tolerance") && !d["tolerance"].is_none()) {
        const py::object t = d["tolerance"];
        if (py::isinstance<py::str>(t))
            r.tolerance = t.cast<std::string>();
        else if (py::isinstance<py::tuple>(t) || py::isinstance<py::list>(t))
            r.tolerance = joined_numbers(t);
        else
            r.tolerance = number_text(t);
    }
    r.duration = get<double>(d, "duration");
    r.dt = get<double>(d, "dt");
    apply_error_estimate(d, r);
    return r;
}

app::RenderRequest render_request(const py::dict& d) {
    app::RenderRequest r;
    r.output = get<std::string>(d, "output").value_or("");
    r.width = get<int>(d, "width");
    r.height = get<int>(d, "height");
    r.fps = get<int>(d, "fps");
    r.frame = get<std::int64_t>(d, "frame");
    r.time = get<double>(d, "time");
    r.crf = get<int>(d, "crf").value_or(r.crf);
    r.preset = get<std::string>(d, "preset");
    r.preview = get<bool>(d, "preview").value_or(false);
    r.shadows = get<bool>(d, "shadows");
    r.soft_shadows = get<bool>(d, "soft_shadows");
    r.ambient_occlusion = get<bool>(d, "ambient_occlusion");
    r.reflections = get<bool>(d, "reflections");
    r.antialiasing = get<bool>(d, "antialiasing");
    r.overlay = get<bool>(d, "overlay");
    r.axes = get<bool>(d, "axes");
    r.vectors = get<bool>(d, "vectors");
    r.chart = get<std::vector<std::string>>(d, "chart");
    r.chart_body = get<std::string>(d, "chart_body");
    r.poinsot = get<std::string>(d, "poinsot");
    r.overlay_body = get<std::string>(d, "overlay_body");
    r.trail_axis = get<std::string>(d, "trail_axis");
    r.chart_window = get<double>(d, "chart_window");
    r.trail_seconds = get<double>(d, "trail_seconds");
    r.trails = get<bool>(d, "trails");
    r.overwrite = get<bool>(d, "overwrite").value_or(false);
    r.compare = get<std::vector<std::string>>(d, "compare").value_or(std::vector<std::string>{});
    return r;
}

} // namespace tumble::python
