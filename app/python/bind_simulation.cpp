// tumble.Simulation: a prepared run (app/run/prepare_run.h) stepped by hand, its state read as
// NumPy arrays at any step: MuJoCo's mj_step and mjData, for Tumble. Its steps are those of
// `tumble simulate` (the same step h, the same contact stage), so after k steps it holds row k of
// simulate's trajectory.
#include "app/python/bindings.h"
#include "app/python/call_scope.h"
#include "app/python/requests.h"

#include "app/run/prepare_run.h"
#include "app/run/run_estimate.h"
#include "app/run/trajectory_rows.h"
#include "io/bad_input.h"
#include "physics/diagnostics.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace tumble::python {
namespace py = pybind11;

namespace {

class Simulation {
  public:
    Simulation(const py::handle& scene_arg, const py::dict& run, std::optional<int> fps,
               int threads)
        : run_(prepare(scene_arg, run, fps, threads)) {
        const physics::Model& m = run_.sim.model;
        for (int i = 0; i < m.body_count(); ++i) {
            if (!m.is_dynamic(i)) continue;
            body_.push_back(i);
            names_.push_back(run_.sim.body_names[std::size_t(i)]);
        }
    }

    void step(std::int64_t n) {
        if (n < 0) throw io::BadInput("step(" + std::to_string(n) + "): expected steps >= 0");
        CallScope scope;
        const std::int64_t done = scope.released([&] {
            for (std::int64_t k = 0; k < n; ++k) {
                if (io::InterruptGuard::requested()) return k;
                run_.sim.step();
            }
            return n;
        });
        if (done < n)
            scope.raise_interrupt(
                "interrupted after " + std::to_string(done) + " of " + std::to_string(n) +
                " steps, at t = " + py::repr(py::float_(t())).cast<std::string>() + " s");
    }

    double t() const { return run_.sim.state.time(run_.sim.model); }
    std::int64_t steps() const { return run_.sim.state.step; }
    const app::PreparedRun& run() const { return run_; }
    const std::vector<std::string>& names() const { return names_; }

    // (B, 3) or (B, 4) of the moving bodies, from the CSV's rows (app/run/trajectory_rows.h).
    py::array_t<double> field(int which) const {
        static const std::string unnamed;
        const py::ssize_t cols = which == 1 ? 4 : 3;
        py::array_t<double> a({py::ssize_t(body_.size()), cols});
        double* out = a.mutable_data();
        for (int i : body_) {
            const app::StateRow r = app::state_row(run_.sim.model, run_.sim.state, i, unnamed);
            const physics::Vec3& v = which == 0 ? r.x : which == 2 ? r.v : r.w;
            if (which == 1)
                for (double c : {r.q.w(), r.q.x(), r.q.y(), r.q.z()}) *out++ = c;
            else
                for (double c : {v.x(), v.y(), v.z()}) *out++ = c;
        }
        return a;
    }

    app::DiagnosticsRow diagnostics() const {
        return app::diagnostics_row(run_.sim.model, run_.sim.state);
    }

  private:
    static app::PreparedRun prepare(const py::handle& scene_arg, const py::dict& run,
                                    std::optional<int> fps, int threads) {
        app::Scene scene = scene_argument(scene_arg);
        const app::RunRequest request = run_request(run);
        CallScope scope; // "auto"'s pilot runs may take a while, and stop on Ctrl-C
        return scope.released([&] {
            app::apply_request(scene, request);
            if (fps) scene.render.fps = *fps;
            return app::prepare_run(std::move(scene), {threads});
        });
    }

    app::PreparedRun run_;
    std::vector<int> body_;
    std::vector<std::string> names_;
};

py::array_t<double> vec3(const physics::Vec3& v) {
    py::array_t<double> a(3);
    double* out = a.mutable_data();
    out[0] = v.x();
    out[1] = v.y();
    out[2] = v.z();
    return a;
}

} // namespace

void bind_simulation(py::module_& m) {
    using S = Simulation;
    py::class_<S>(m, "_Simulation",
                  "A scene made ready to step by hand: sim.step(n), then read the state (sim.t, "
                  "sim.position, ...). The same steps as tumble.simulate and `tumble simulate`: "
                  "after k steps it holds their row of step k.")
        .def(py::init([](const py::handle& scene, const py::dict& run, std::optional<int> fps,
                         int threads) { return new S(scene, run, fps, threads); }),
             py::arg("scene"), py::arg("run"), py::arg("fps"), py::arg("threads"))
        .def("step", &S::step, py::arg("n") = 1,
             "Takes n physics steps of dt each (KeyboardInterrupt stops it between steps).")
        .def_property_readonly("t", &S::t, "the time, s (steps * dt)")
        .def_property_readonly("steps", &S::steps, "physics steps taken")
        .def_property_readonly(
            "dt", [](const S& s) { return s.run().timeline.h; },
            "the step h, s: the scene's dt, or lowered so that steps land on frame times")
        .def_property_readonly("integrator",
                               [](const S& s) {
                                   return std::string(
                                       physics::integrator_info(s.run().sim.model.integrator).name);
                               })
        .def_property_readonly(
            "steps_per_frame", [](const S& s) { return s.run().timeline.steps_per_frame; },
            "steps between frames: frame k shows the state after k * steps_per_frame steps")
        .def_property_readonly("bodies", &S::names, "the moving bodies' names: the arrays' rows")
        .def_property_readonly(
            "position", [](const S& s) { return s.field(0); },
            "(B, 3) each moving body's origin, world, m")
        .def_property_readonly(
            "orientation", [](const S& s) { return s.field(1); },
            "(B, 4) each moving body's orientation, body -> world, quaternion w, x, y, z")
        .def_property_readonly(
            "velocity", [](const S& s) { return s.field(2); },
            "(B, 3) velocity of each centre of mass, world, m/s")
        .def_property_readonly(
            "angular_velocity", [](const S& s) { return s.field(3); },
            "(B, 3) angular velocity w, world, rad/s")
        .def_property_readonly(
            "energy", [](const S& s) { return s.diagnostics().energy; }, "total energy, J")
        .def_property_readonly(
            "kinetic", [](const S& s) { return s.diagnostics().kinetic; }, "kinetic energy, J")
        .def_property_readonly(
            "potential", [](const S& s) { return s.diagnostics().potential; },
            "gravitational potential energy, J")
        .def_property_readonly(
            "momentum", [](const S& s) { return vec3(s.diagnostics().p); },
            "(3,) linear momentum P, kg m/s")
        .def_property_readonly(
            "angular_momentum", [](const S& s) { return vec3(s.diagnostics().l); },
            "(3,) angular momentum L about the world origin, kg m^2/s")
        .def_property_readonly(
            "notes", [](const S& s) { return s.run().notes(1); },
            "what the command line prints as 'tumble: note:' (dt lowered, ...)")
        .def_property_readonly(
            "summary", [](const S& s) { return app::estimate_summary(s.run().sim); },
            "the error estimate's summary so far (when the scene or error_estimate= asks)")
        .def("__repr__", [](const S& s) {
            return "<tumble.Simulation " + s.run().scene.source +
                   " at t = " + py::repr(py::float_(s.t())).cast<std::string>() + " s, step " +
                   std::to_string(s.steps()) + ">";
        });
}

} // namespace tumble::python
