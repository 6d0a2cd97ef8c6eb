#include "app/study/runner.h"
#include "app/study/metrics.h"
#include "io/interrupt.h"
#include "physics/integrator.h"
#include "physics/step.h"
#include "physics/stop.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <time.h>

namespace tumble::app::study {

using physics::State;

void parallel_for(int count, int threads, const std::function<void(int)>& fn) {
    std::atomic<int> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    const auto worker = [&] {
        for (int i = next++; i < count; i = next++) {
            try {
                io::InterruptGuard::stop_if_requested("the study");
                fn(i);
            } catch (...) {
                const std::lock_guard lock(error_mutex);
                if (!error) error = std::current_exception();
                next = count; // stop handing out work
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min(threads, count); ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

double thread_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

namespace {

Errors not_a_number() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan, nan};
}

// Steps the whole run, measuring the errors at the sample times. A divergence is a result.
void accuracy_run(const Problem& p, const Reference& ref, physics::Integrator id, Row& row) {
    Setup s = make_setup(p, id, row.dt);
    const std::int64_t per_sample = row.steps / kSamples;
    try {
        for (std::int64_t k = 1; k <= row.steps; ++k) {
            if (k % physics::kStopPollSteps == 0)
                io::InterruptGuard::stop_if_requested("the study");
            physics::step(s.model, s.state);
            if (k % per_sample != 0) continue;
            const auto j = static_cast<std::size_t>(k / per_sample);
            const Errors e = measure(s.model, s.state, ref.states[j], ref.diagnostics[j]);
            keep_max(row.max, e);
            if (k == row.steps) row.end = e;
        }
    } catch (const physics::DivergenceError& d) {
        row.diverged = true;
        row.diverged_body = d.body;
        row.diverged_step = d.step;
        row.diverged_quantity = d.quantity;
        row.end = row.max = not_a_number();
    }
}

// One pass of the stepping loop from the initial state; returns the steps taken (a diverging
// run stops at its divergence) and adds the loop's CPU time to `seconds`.
std::int64_t timed_pass(const Setup& s, State& work, std::int64_t steps, double& seconds) {
    work = s.state;
    const double t0 = thread_seconds();
    try {
        for (std::int64_t k = 0; k < steps; ++k) physics::step(s.model, work);
    } catch (const physics::DivergenceError&) {
    }
    seconds += thread_seconds() - t0;
    return work.step;
}

void timing_run(const Problem& p, physics::Integrator id, const TimingSettings& t, Row& row) {
    const Setup s = make_setup(p, id, row.dt);
    State work = s.state;
    double warm = 0.0;
    const std::int64_t taken = std::max<std::int64_t>(1, timed_pass(s, work, row.steps, warm));
    const int batch =
        static_cast<int>(std::clamp(std::ceil(t.min_rep_seconds / std::max(warm, 1e-9)), 1.0, 1e6));
    std::vector<double> ns;
    for (int r = 0; r < t.repetitions; ++r) {
        double seconds = 0.0;
        for (int b = 0; b < batch; ++b) {
            io::InterruptGuard::stop_if_requested("the study"); // between timed passes
            timed_pass(s, work, row.steps, seconds);
        }
        ns.push_back(1e9 * seconds / (double(batch) * double(taken) * row.bodies));
    }
    std::sort(ns.begin(), ns.end());
    const std::size_t mid = ns.size() / 2;
    row.ns_per_body_step = ns.size() % 2 ? ns[mid] : 0.5 * (ns[mid - 1] + ns[mid]);
    row.steps_per_second = 1e9 / (row.ns_per_body_step * row.bodies);
    row.cost_s = 1e-9 * row.ns_per_body_step * row.bodies * double(row.steps);
    row.repetitions = t.repetitions;
}

struct Job {
    int problem;
    const physics::IntegratorInfo* info;
    std::int64_t steps;
};

bool is_skipped(const std::vector<Skip>& skipped, const Problem& p,
                const physics::IntegratorInfo& info) {
    for (const Skip& s : skipped)
        if (s.problem == p.name && s.integrator == info.name) return true;
    return false;
}

// No body of the problem has an applied torque: the exact-flow methods truncate nothing on it.
bool torque_free(const Problem& p) {
    for (const physics::BodyDef& b : p.bodies())
        if (b.applied_torque != physics::Vec3::Zero()) return false;
    return true;
}

} // namespace

std::vector<Skip> refused_pairs(const std::vector<Problem>& problems) {
    std::vector<Skip> out;
    for (const Problem& p : problems)
        for (const physics::IntegratorInfo& info : physics::integrators()) {
            try {
                make_setup(p, info.id, p.duration / kSamples);
            } catch (const physics::ModelError& e) {
                out.push_back({p.name, std::string(info.name), e.what()});
            }
        }
    return out;
}

std::vector<Row> run_grid(const std::vector<Problem>& problems, bool quick, int threads,
                          const TimingSettings& timing, const std::vector<Skip>& skipped,
                          const std::function<void(int, int)>& progress) {
    std::vector<Reference> refs(problems.size());
    parallel_for(static_cast<int>(problems.size()), threads,
                 [&](int i) { refs[i] = make_reference(problems[i], quick); });

    std::vector<Job> jobs;
    for (std::size_t i = 0; i < problems.size(); ++i)
        for (const physics::IntegratorInfo& info : physics::integrators()) {
            if (is_skipped(skipped, problems[i], info)) continue;
            for (std::int64_t n : step_counts(problems[i], quick))
                jobs.push_back({static_cast<int>(i), &info, n});
        }

    std::vector<Row> rows(jobs.size());
    std::mutex progress_mutex;
    int done = 0;
    parallel_for(static_cast<int>(jobs.size()), threads, [&](int j) {
        const Job& job = jobs[j];
        const Problem& p = problems[job.problem];
        Row& row = rows[j];
        row.problem = p.name;
        row.integrator = std::string(job.info->name);
        row.order = job.info->order;
        row.contacts = p.contacts;
        row.exact_here = job.info->exact_without_torque && !p.contacts && torque_free(p);
        row.steps = job.steps;
        row.dt = p.duration / static_cast<double>(job.steps);
        row.h_w = row.dt * largest_spin(p);
        row.bodies =
            static_cast<int>(make_setup(p, job.info->id, row.dt).model.dynamic_bodies.size());
        accuracy_run(p, refs[job.problem], job.info->id, row);
        timing_run(p, job.info->id, timing, row);
        const std::lock_guard lock(progress_mutex);
        progress(++done, static_cast<int>(jobs.size()));
    });
    return rows;
}

EnergyTrace energy_trace(const Problem& p, const std::string& integrator, double dt, double t_end) {
    EnergyTrace out{integrator, {}, false};
    Setup s = make_setup(p, physics::integrator_from_name(integrator).value(), dt);
    const double e0 = physics::diagnose(s.model, s.state).energy();
    const std::int64_t n = std::llround(t_end / dt), stride = std::max<std::int64_t>(1, n / 1000);
    out.points.emplace_back(0.0, 0.0);
    try {
        for (std::int64_t k = 1; k <= n; ++k) {
            if (k % physics::kStopPollSteps == 0)
                io::InterruptGuard::stop_if_requested("the study");
            physics::step(s.model, s.state);
            if (k % stride != 0 && k != n) continue;
            const double e = physics::diagnose(s.model, s.state).energy();
            out.points.emplace_back(s.state.time(s.model), std::abs(e - e0) / std::abs(e0));
        }
    } catch (const physics::DivergenceError&) {
        out.diverged = true;
    }
    return out;
}

} // namespace tumble::app::study
