// tumble.Trajectory and simulate(): `tumble simulate` from Python. The arrays are read-only NumPy
// views of the trajectory's own vectors (no copy, no per-row Python object), so a long run costs
// what the stepping costs.
#include "app/python/bindings.h"
#include "app/python/call_scope.h"
#include "app/python/requests.h"
#include "app/python/trajectory.h"

#include "app/run/stale_temporaries.h"
#include "app/run/trajectory_writer.h"
#include "io/bad_input.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>

namespace tumble::python {
namespace py = pybind11;

namespace {

// A read-only view of `data` shaped `shape`, kept alive by `owner`.
template <class T>
py::array view(const std::vector<T>& data, std::vector<py::ssize_t> shape, py::handle owner) {
    py::array_t<T> a(shape, data.data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

// Rows x bodies of the estimate's rotation (or position) error; NaN where it no longer holds.
py::object estimate_array(const Trajectory& tr, bool rotation) {
    if (tr.estimate_bodies == 0) return py::none();
    py::array_t<double> a({py::ssize_t(tr.rows), py::ssize_t(tr.estimate_bodies)});
    double* out = a.mutable_data();
    for (std::size_t i = 0; i < tr.estimate.size(); ++i) {
        const physics::BodyEstimate& b = tr.estimate[i];
        out[i] = !b.holds() ? std::numeric_limits<double>::quiet_NaN()
                 : rotation ? b.at.rotation
                            : b.at.position;
    }
    return a;
}

// The CLI's --diagnostics: None beside the states (<stem>.diagnostics.csv), "none" or False for
// none, else a path.
std::string diagnostics_path(const std::string& states, const py::object& diagnostics) {
    if (diagnostics.is_none()) return app::diagnostics_path_for(states);
    if (py::isinstance<py::bool_>(diagnostics)) {
        if (!diagnostics.cast<bool>()) return "";
        return app::diagnostics_path_for(states);
    }
    const std::string path =
        py::module_::import("os").attr("fspath")(diagnostics).cast<std::string>();
    if (path == "none") return "";
    if (path == states)
        throw io::BadInput("--diagnostics " + path +
                           ": the states already go there; two tables cannot share one output");
    return path;
}

Trajectory simulate(const py::handle& scene_argument_, const py::dict& run, int every,
                    std::optional<int> fps, int threads, bool progress) {
    (void)progress; // stepping draws no bar: the loop is too fast to need one
    if (every < 1)
        throw io::BadInput("--every " + std::to_string(every) + ": expected a positive number");
    app::Scene scene = scene_argument(scene_argument_);
    const app::RunRequest request = run_request(run);
    CallScope scope;
    Trajectory out;
    const bool finished = scope.released([&] {
        app::apply_request(scene, request);
        if (fps) scene.render.fps = *fps; // as `tumble simulate --fps`: the same frame times
        app::PreparedRun prepared = app::prepare_run(std::move(scene), {threads});
        out = start_trajectory(prepared);
        return simulate_into(prepared, every, out);
    });
    if (!finished)
        scope.raise_interrupt(
            "interrupted at t = " + py::repr(py::float_(out.t.back())).cast<std::string>() +
            " s; the trajectory so far is not returned");
    for (const std::string& line : out.tolerance_missed) warn(line);
    return out;
}

} // namespace

void bind_trajectory(py::module_& m) {
    using T = Trajectory;
    py::class_<T>(m, "Trajectory",
                  "The states and diagnostics of a run (tumble.simulate), one row per sampled "
                  "step, as read-only NumPy arrays; the numbers `tumble simulate` writes.")
        .def("__len__", [](const T& t) { return t.rows; })
        .def_property_readonly(
            "t",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.t, {t.rows}, self);
            },
            "(T,) time of each row, s")
        .def_property_readonly(
            "step",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.step, {t.rows}, self);
            },
            "(T,) the step of each row (t = step * dt)")
        .def_readonly("bodies", &T::names, "the moving bodies' names: the arrays' second axis")
        .def_property_readonly(
            "position",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.position, {t.rows, py::ssize_t(t.body.size()), 3}, self);
            },
            "(T, B, 3) each body's origin (the scene's position), world, m")
        .def_property_readonly(
            "orientation",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.orientation, {t.rows, py::ssize_t(t.body.size()), 4}, self);
            },
            "(T, B, 4) each body's orientation, body -> world, as a unit quaternion w, x, y, z")
        .def_property_readonly(
            "velocity",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.velocity, {t.rows, py::ssize_t(t.body.size()), 3}, self);
            },
            "(T, B, 3) velocity of each body's centre of mass, world, m/s")
        .def_property_readonly(
            "angular_velocity",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.w, {t.rows, py::ssize_t(t.body.size()), 3}, self);
            },
            "(T, B, 3) angular velocity w, world, rad/s")
        .def_property_readonly(
            "kinetic",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.kinetic, {t.rows}, self);
            },
            "(T,) kinetic energy of the scene, J")
        .def_property_readonly(
            "potential",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.potential, {t.rows}, self);
            },
            "(T,) gravitational potential energy, J (zero at the world origin)")
        .def_property_readonly(
            "energy",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.energy, {t.rows}, self);
            },
            "(T,) total energy, kinetic + potential, J")
        .def_property_readonly(
            "momentum",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.momentum, {t.rows, 3}, self);
            },
            "(T, 3) linear momentum P of the scene, kg m/s")
        .def_property_readonly(
            "angular_momentum",
            [](py::object self) {
                const T& t = self.cast<const T&>();
                return view(t.angular_momentum, {t.rows, 3}, self);
            },
            "(T, 3) angular momentum L about the world origin, world, kg m^2/s")
        .def_property_readonly(
            "error_rotation", [](const T& t) { return estimate_array(t, true); },
            "(T, B) the error estimate's orientation error of each moving body, rad (NaN once "
            "a contact or sleep ends it); None without error_estimate")
        .def_property_readonly(
            "error_position", [](const T& t) { return estimate_array(t, false); },
            "(T, B) the error estimate's position error, m; None without error_estimate")
        .def_readonly("integrator", &T::integrator, "the integrator that ran (auto's choice)")
        .def_readonly("dt", &T::h,
                      "the step that ran, s (the scene's, or lowered to land on frame times)")
        .def_readonly("fps", &T::fps)
        .def_readonly("notes", &T::notes, "what the command line prints as 'tumble: note:'")
        .def_readonly("summary", &T::summary,
                      "the run summary's lines: auto's choice, the error estimate, the tolerance")
        .def(
            "write_csv",
            [](const T& t, const py::object& path, const py::object& diagnostics) {
                const std::string states =
                    py::module_::import("os").attr("fspath")(path).cast<std::string>();
                const std::string diags = diagnostics_path(states, diagnostics);
                for (const std::string& p : {states, diags})
                    if (!p.empty()) app::remove_stale_temporaries_for(p, true);
                py::gil_scoped_release release;
                t.write_csv(states, diags);
            },
            py::arg("path"), py::arg("diagnostics") = py::none(),
            "Writes the CSV files `tumble simulate -o PATH` writes, byte for byte: the states, "
            "and the diagnostics beside them (<stem>.diagnostics.csv), or at `diagnostics`, or "
            "none for diagnostics='none' or False.")
        .def("__repr__",
             [](const T& t) {
                 return "<tumble.Trajectory " + std::to_string(t.rows) + " rows x " +
                        std::to_string(t.body.size()) + " bodies, " + t.integrator + ", t = 0 .. " +
                        py::repr(py::float_(t.t.back())).cast<std::string>() + " s>";
             })
        .attr("__module__") = "tumble";

    m.def("_simulate", &simulate, py::arg("scene"), py::arg("run"), py::arg("every"),
          py::arg("fps"), py::arg("threads"), py::arg("progress"));
}

} // namespace tumble::python
