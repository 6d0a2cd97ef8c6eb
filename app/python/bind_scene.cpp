// tumble.Scene: a scene as loaded and checked (app/scene), before any override; every call takes
// one (or what load() takes) and applies its keywords to a copy.
#include "app/python/bindings.h"
#include "app/python/requests.h"

#include "physics/integrator.h"

#include <pybind11/stl.h>

namespace tumble::python {
namespace py = pybind11;

namespace {

std::vector<std::string> body_names(const app::Scene& s, bool moving_only) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
        if (!moving_only || s.bodies[i].motion == physics::Motion::Dynamic)
            out.push_back(s.looks[i].name);
    return out;
}

std::string describe(const app::Scene& s) {
    return "<tumble.Scene " + s.source + ": " + std::to_string(s.bodies.size()) + " bodies, " +
           py::repr(py::float_(s.duration)).cast<std::string>() + " s>";
}

} // namespace

void bind_scene(py::module_& m) {
    py::class_<app::Scene>(m, "Scene",
                           "A scene as loaded and checked (tumble.load): the file's settings, "
                           "before the keywords of a call override them. Calls copy it.")
        .def_readonly("source", &app::Scene::source,
                      "where it came from: a file path, 'builtin:<name>.json' or '<dict>'")
        .def_readonly("title", &app::Scene::title)
        .def_readonly("duration", &app::Scene::duration, "simulated time, s")
        .def_property_readonly(
            "dt", [](const app::Scene& s) { return s.world.dt; },
            "the time step asked for, s (a run may lower it to land on frame times)")
        .def_property_readonly(
            "integrator",
            [](const app::Scene& s) {
                return s.accuracy.auto_integrator
                           ? std::string("auto")
                           : std::string(physics::integrator_info(s.world.integrator).name);
            },
            "the integrator's name, or 'auto' (chosen for world.tolerance)")
        .def_property_readonly(
            "fps", [](const app::Scene& s) { return s.render.fps; }, "frames per second")
        .def_property_readonly(
            "size",
            [](const app::Scene& s) { return py::make_tuple(s.render.width, s.render.height); },
            "(width, height) of its frames, pixels")
        .def_property_readonly(
            "bodies", [](const app::Scene& s) { return body_names(s, false); },
            "every body's name, in the scene's order")
        .def_property_readonly(
            "moving_bodies", [](const app::Scene& s) { return body_names(s, true); },
            "the names of the dynamic bodies: the bodies of a Trajectory's arrays")
        .def_readonly("warnings", &app::Scene::warnings, "what loading it warned about")
        .def("__repr__", &describe)
        .attr("__module__") = "tumble";

    m.def("_load", &load_argument, py::arg("scene"));
    m.def(
        "scenes", [] { return app::builtin_scene_names(); },
        "The built-in scenes' names (tumble.load takes each), as `tumble scenes` lists them.");
    m.def(
        "integrators",
        [] {
            std::vector<std::string> out;
            for (const physics::IntegratorInfo& i : physics::integrators())
                out.emplace_back(i.name);
            return out;
        },
        "The integrators' names (docs/integrators.md), as integrator= and compare= take them.");
}

} // namespace tumble::python
