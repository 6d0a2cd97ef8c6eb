#include "app/python/trajectory.h"

#include "app/run/accuracy_choice.h"
#include "app/run/run_estimate.h"
#include "app/run/trajectory_writer.h"
#include "io/interrupt.h"

#include <span>

namespace tumble::python {
namespace {

void push(std::vector<double>& to, const physics::Vec3& v) {
    to.insert(to.end(), {v.x(), v.y(), v.z()});
}

} // namespace

Trajectory start_trajectory(const app::PreparedRun& run) {
    const app::Simulation& sim = run.sim;
    Trajectory out;
    out.scene = run.scene;
    out.integrator = physics::integrator_info(sim.model.integrator).name;
    out.h = run.timeline.h;
    out.fps = run.timeline.fps;
    for (int i = 0; i < sim.model.body_count(); ++i) {
        if (sim.model.is_dynamic(i)) {
            out.body.push_back(i);
            out.names.push_back(sim.body_names[std::size_t(i)]);
        } else {
            out.static_rows.push_back(
                app::state_row(sim.model, sim.state, i, sim.body_names[std::size_t(i)]));
        }
    }
    if (sim.estimate.estimator) out.estimate_bodies = int(sim.estimate.estimator->bodies().size());
    out.notes = run.notes(1);
    out.record(sim);
    return out;
}

void Trajectory::record(const app::Simulation& sim) {
    static const std::string unnamed;
    const physics::Model& m = sim.model;
    const physics::State& s = sim.state;
    step.push_back(s.step);
    t.push_back(s.time(m));
    for (int i : body) {
        const app::StateRow r = app::state_row(m, s, i, unnamed);
        push(position, r.x);
        orientation.insert(orientation.end(), {r.q.w(), r.q.x(), r.q.y(), r.q.z()});
        push(velocity, r.v);
        push(w, r.w);
    }
    const app::DiagnosticsRow d = app::diagnostics_row(m, s);
    kinetic.push_back(d.kinetic);
    potential.push_back(d.potential);
    energy.push_back(d.energy);
    push(momentum, d.p);
    push(angular_momentum, d.l);
    if (estimate_bodies > 0) {
        const auto bodies = sim.estimate.estimator->bodies();
        estimate.insert(estimate.end(), bodies.begin(), bodies.end());
    }
    ++rows;
}

bool simulate_into(app::PreparedRun& run, int every, Trajectory& out) {
    app::Simulation& sim = run.sim;
    const std::int64_t total = run.timeline.end_step(); // the last row at t = duration
    const std::int64_t sampled = total / every + 2;
    for (std::vector<double>* v : {&out.position, &out.velocity, &out.w})
        v->reserve(std::size_t(sampled) * out.body.size() * 3);
    out.orientation.reserve(std::size_t(sampled) * out.body.size() * 4);
    bool finished = true;
    for (std::int64_t k = 1; k <= total; ++k) {
        if (io::InterruptGuard::requested()) {
            finished = false;
            break;
        }
        sim.step();
        if (k % every == 0 || k == total) out.record(sim);
    }
    out.summary = app::describe_choice(run.scene, true);
    for (const std::string& line : app::estimate_summary(sim)) out.summary.push_back(line);
    if (run.scene.accuracy.tolerance && sim.estimate.estimator) {
        const app::ToleranceCheck check = app::check_tolerance(
            *run.scene.accuracy.tolerance,
            {sim.estimate.estimator->bodies().begin(), sim.estimate.estimator->bodies().end()},
            sim.body_names);
        for (const std::string& line : check.lines) {
            out.summary.push_back(line);
            if (line.starts_with("warning: ")) out.tolerance_missed.push_back(line.substr(9));
        }
    }
    return finished;
}

void Trajectory::write_csv(const std::string& states, const std::string& diagnostics) const {
    const std::span<const physics::BodyEstimate> first(estimate.data(),
                                                       std::size_t(estimate_bodies));
    app::TrajectoryWriter out(states, diagnostics, scene, first);
    const std::size_t bodies = body.size() + static_rows.size();
    std::vector<app::StateRow> rows(bodies);
    std::vector<int> moving(bodies, -1); // index into `body`, or -1 for a static body
    for (std::size_t b = 0; b < body.size(); ++b) moving[std::size_t(body[b])] = int(b);
    for (std::int64_t r = 0; r < this->rows; ++r) {
        std::size_t next_static = 0;
        for (std::size_t i = 0; i < bodies; ++i) {
            app::StateRow& row = rows[i];
            if (moving[i] < 0) {
                row = static_rows[next_static++];
            } else {
                const std::size_t at = std::size_t(r) * body.size() + std::size_t(moving[i]);
                const double* q = &orientation[4 * at];
                row = {0,
                       0.0,
                       int(i),
                       names[std::size_t(moving[i])],
                       {position[3 * at], position[3 * at + 1], position[3 * at + 2]},
                       physics::Quat(q[0], q[1], q[2], q[3]),
                       {velocity[3 * at], velocity[3 * at + 1], velocity[3 * at + 2]},
                       {w[3 * at], w[3 * at + 1], w[3 * at + 2]}};
            }
            row.step = step[std::size_t(r)];
            row.t = t[std::size_t(r)];
        }
        const std::size_t k = std::size_t(r);
        const app::DiagnosticsRow d{
            step[k],
            t[k],
            kinetic[k],
            potential[k],
            energy[k],
            {momentum[3 * k], momentum[3 * k + 1], momentum[3 * k + 2]},
            {angular_momentum[3 * k], angular_momentum[3 * k + 1], angular_momentum[3 * k + 2]}};
        out.write(rows, d,
                  std::span<const physics::BodyEstimate>(estimate.data() +
                                                             k * std::size_t(estimate_bodies),
                                                         std::size_t(estimate_bodies)));
    }
    out.finish();
}

} // namespace tumble::python
