#include "app/study/metrics.h"

#include "io/interrupt.h"
#include "physics/exact/body_motion.h"
#include "physics/integrator.h"
#include "physics/step.h"
#include "physics/stop.h"

#include <algorithm>
#include <cmath>

namespace tumble::app::study {

using physics::Diagnostics;
using physics::Model;
using physics::State;
using physics::Vec3;

Setup make_setup(const Problem& p, physics::Integrator integrator, double dt) {
    physics::WorldDef world = p.world();
    world.integrator = integrator;
    world.dt = dt;
    const std::vector<physics::BodyDef> bodies = p.bodies();
    Setup s{physics::build_model(world, bodies), {}};
    s.state = physics::initial_state(s.model, bodies);
    return s;
}

namespace {

Reference exact_reference(const Problem& p) {
    // The integrator is irrelevant here: only the model's bodies and loads are read.
    const Setup s = make_setup(p, physics::integrators().front().id, p.duration / kSamples);
    std::vector<exact::ExactBodyMotion> motion;
    for (int i : s.model.dynamic_bodies) motion.emplace_back(s.model, s.state, i);
    Reference ref;
    for (int j = 0; j <= kSamples; ++j) {
        State st = s.state;
        st.step = j;
        const double t = p.duration * j / kSamples;
        for (std::size_t k = 0; k < motion.size(); ++k) {
            const int i = s.model.dynamic_bodies[k];
            const exact::BodyState b = motion[k].at(t);
            st.x[i] = b.x, st.q[i] = b.q, st.v[i] = b.v, st.w[i] = b.w;
        }
        ref.diagnostics.push_back(physics::diagnose(s.model, st));
        ref.states.push_back(std::move(st));
    }
    return ref;
}

Reference analytic_reference(const Problem& p) {
    const Setup s = make_setup(p, physics::integrators().front().id, p.duration / kSamples);
    Reference ref;
    for (int j = 0; j <= kSamples; ++j) {
        State st = s.state;
        st.step = j;
        p.analytic(p.duration * j / kSamples, s.model, st);
        ref.diagnostics.push_back(physics::diagnose(s.model, st));
        ref.states.push_back(std::move(st));
    }
    return ref;
}

// The first integrator of the registry with the highest theoretical order.
physics::Integrator most_accurate() {
    const physics::IntegratorInfo* best = &physics::integrators().front();
    for (const physics::IntegratorInfo& info : physics::integrators())
        if (info.order > best->order) best = &info;
    return best->id;
}

Reference converged_reference(const Problem& p, bool quick) {
    const std::int64_t n = step_counts(p, quick).back() * p.reference_refine;
    const std::int64_t per_sample = n / kSamples;
    Setup s = make_setup(p, most_accurate(), p.duration / static_cast<double>(n));
    Reference ref;
    ref.states.push_back(s.state);
    ref.diagnostics.push_back(physics::diagnose(s.model, s.state));
    for (std::int64_t k = 1; k <= n; ++k) {
        if (k % physics::kStopPollSteps == 0) io::InterruptGuard::stop_if_requested("the study");
        physics::step(s.model, s.state); // a diverging reference is a bug: let it throw
        if (k % per_sample == 0) {
            ref.states.push_back(s.state);
            ref.diagnostics.push_back(physics::diagnose(s.model, s.state));
        }
    }
    return ref;
}

double relative(const Vec3& a, const Vec3& ref) {
    const double d = (a - ref).norm(), scale = ref.norm();
    return scale > 0.0 ? d / scale : d;
}

} // namespace

Reference make_reference(const Problem& p, bool quick) {
    switch (p.reference) {
    case ReferenceKind::Exact:
        return exact_reference(p);
    case ReferenceKind::Analytic:
        return analytic_reference(p);
    case ReferenceKind::ConvergedRun:
        break;
    }
    return converged_reference(p, quick);
}

Errors measure(const Model& model, const State& run, const State& ref, const Diagnostics& ref_d) {
    Errors e;
    for (int i : model.dynamic_bodies) {
        e.position = std::max(e.position, (run.x[i] - ref.x[i]).norm());
        e.orientation =
            std::max(e.orientation, physics::rotation_angle_between(ref.q[i], run.q[i]));
        e.angular_velocity = std::max(e.angular_velocity, relative(run.w[i], ref.w[i]));
    }
    const Diagnostics d = physics::diagnose(model, run);
    e.energy = std::abs(d.energy() - ref_d.energy()) / std::abs(ref_d.energy());
    e.momentum = relative(d.angular_momentum, ref_d.angular_momentum);
    return e;
}

void keep_max(Errors& max, const Errors& e) {
    // std::max(a, NaN) would keep a: a NaN error must win, so compare the other way round.
    const auto worse = [](double m, double v) { return std::isnan(v) || v > m ? v : m; };
    max.position = worse(max.position, e.position);
    max.orientation = worse(max.orientation, e.orientation);
    max.angular_velocity = worse(max.angular_velocity, e.angular_velocity);
    max.energy = worse(max.energy, e.energy);
    max.momentum = worse(max.momentum, e.momentum);
}

double largest_spin(const Problem& p) {
    double w = 0.0;
    for (const physics::BodyDef& b : p.bodies())
        if (b.motion == physics::Motion::Dynamic) w = std::max(w, b.angular_velocity.norm());
    return w;
}

} // namespace tumble::app::study
