// `tumble study [--quick] [-o DIR] [--threads N] [--peers FILE]`: runs the work-precision grid, the
// stability map of free bodies and of contacts and the contacts' effort settings, then writes
// DIR/study.csv, DIR/study.json, DIR/contact_stability.csv, DIR/contact_effort.csv,
// DIR/plots/*.png and DIR/report.md.
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/run/progress.h"
#include "app/study/analysis.h"
#include "app/study/auto_check.h"
#include "app/study/metrics.h"
#include "app/study/plots.h"
#include "app/study/report.h"
#include "app/study/runner.h"
#include "app/study/stability.h"
#include "io/atomic_file.h"
#include "io/bad_input.h"
#include "io/interrupt.h"
#include "physics/integrator.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

namespace tumble::app {
namespace {

using namespace study;

struct StudyCommand {
    bool quick = false;           // the small grid CI runs (under a minute on 2 cores)
    std::string output = "study"; // folder for study.csv, study.json, report.md and plots/
    int threads = 0;              // 0: one per hardware thread
    bool quiet = false;
    bool auto_check = false; // --auto: check "auto"'s plans against the exact answers
    std::string peers;       // --peers FILE: ODE's points in the contacts' work-precision view
};
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The energy plot: the headline problem at its grid step nearest h|w| = 0.05, for four horizons.
void energy_traces(Results& r, int threads) {
    const Problem& p = problems().front();
    double best = 0.0;
    for (std::int64_t n : step_counts(p, r.quick)) {
        const double dt = p.duration / double(n);
        if (best == 0.0 || std::abs(std::log(dt * largest_spin(p) / 0.05)) <
                               std::abs(std::log(best * largest_spin(p) / 0.05)))
            best = dt;
    }
    r.energy_problem = p.name;
    r.energy_dt = best;
    r.energy_t_end = 4.0 * p.duration;
    const auto infos = physics::integrators();
    r.energy.resize(infos.size());
    parallel_for(static_cast<int>(infos.size()), threads, [&](int i) {
        r.energy[i] = energy_trace(p, std::string(infos[i].name), best, r.energy_t_end);
    });
}

void print_summary(const Results& r, const std::string& dir) {
    if (r.auto_checked) {
        const AutoSummary s = summarise(r.auto_cases);
        std::printf("auto (%d cases the estimate covers, of %d): estimate within 3x %d, "
                    "tolerance met %d, cost <= 2x the grid's cheapest %d\n",
                    s.covered, s.cases, s.within_3, s.meets, s.cost_within_2);
    }
    std::printf("recommendation (orientation error, max over [0, T]):\n");
    for (const Recommendation& rec : r.recommendations) {
        if (!rec.row) {
            std::printf("  %-18s %s  not reached on the grid\n", rec.problem.c_str(),
                        sci(rec.target, 0).c_str());
            continue;
        }
        std::printf("  %-18s %s  %-16s h = %-9.3g error %s  cost %.3g ms\n", rec.problem.c_str(),
                    sci(rec.target, 0).c_str(), rec.row->integrator.c_str(), rec.row->dt,
                    sci(headline_error(*rec.row)).c_str(), 1e3 * rec.row->cost_s);
    }
    std::printf(
        "wrote %s/report.md, study.csv, study.json, contact_stability.csv, contact_effort.csv and "
        "plots/ in %.1f s\n",
        dir.c_str(), r.seconds_total);
}

// The work-precision grid, with a progress bar over its runs.
void run_grid_with_progress(Results& r, const StudyCommand& cmd) {
    r.skipped = refused_pairs(problems());
    std::size_t runs = 0;
    for (const Problem& p : problems())
        runs += step_counts(p, cmd.quick).size() * physics::integrators().size();
    for (const Skip& k : r.skipped)
        for (const Problem& p : problems())
            if (p.name == k.problem) runs -= step_counts(p, cmd.quick).size();
    if (!cmd.quiet) {
        std::fprintf(stderr,
                     "tumble study: %zu problems x %zu integrators, %zu runs on %d threads\n",
                     problems().size(), physics::integrators().size(), runs, r.threads);
        for (const Skip& k : r.skipped)
            std::fprintf(stderr, "tumble study: skipping %s on %s: %s\n", k.integrator.c_str(),
                         k.problem.c_str(), k.reason.c_str());
    }
    Progress progress("runs", static_cast<std::int64_t>(runs), cmd.quiet);
    const Clock::time_point t0 = Clock::now();
    r.rows = run_grid(problems(), cmd.quick, r.threads, r.timing, r.skipped,
                      [&](int done, int) { progress.update(done); });
    progress.finish();
    r.seconds_grid = seconds_since(t0);
}

// Everything after the set-up: measure, analyse, write. Throws on any failure.
void measure_and_write(Results& r, const StudyCommand& cmd, Clock::time_point start) {
    r.plotter = gnuplot::gnuplot_version(); // before the long part: a missing gnuplot fails at once
    r.machine = describe_machine();
    r.build = describe_build();
    run_grid_with_progress(r, cmd);
    const Clock::time_point t1 = Clock::now();
    r.stability = stability_map(cmd.quick, r.threads);
    r.seconds_stability = seconds_since(t1);
    if (!cmd.quiet)
        std::fprintf(stderr, "tumble study: contact stability map (%zu cases, %s)\n",
                     contact_cases().size(),
                     cmd.quick ? "rk4 and symplectic_euler" : "every integrator");
    const Clock::time_point t2 = Clock::now();
    r.contact_stability = contact_stability_map(cmd.quick, r.threads);
    r.seconds_contacts = seconds_since(t2);
    const Clock::time_point t4 = Clock::now();
    if (!cmd.quiet)
        std::fprintf(stderr, "tumble study: contact effort settings (sphere rain, stack)\n");
    std::vector<EffortPoint> effort = contact_effort_study(cmd.quick ? 1 : 3, r.threads);
    r.contact_effort.insert(r.contact_effort.begin(), effort.begin(), effort.end()); // peers last
    r.seconds_effort = seconds_since(t4);
    energy_traces(r, r.threads);
    if (cmd.auto_check) {
        const Clock::time_point t3 = Clock::now();
        if (!cmd.quiet)
            std::fprintf(stderr, "tumble study: auto's plans, %zu tolerances per problem\n",
                         auto_tolerances().size());
        r.auto_cases = check_auto(problems(), r.rows, auto_tolerances(), cmd.quick, r.threads);
        r.auto_checked = true;
        if (!cmd.quiet)
            std::fprintf(stderr, "tumble study: auto checked in %.1f s\n", seconds_since(t3));
    }

    r.orders = fit_orders(r.rows);
    std::vector<std::string> names;
    for (const Problem& p : problems()) names.push_back(p.name);
    r.recommendations = recommend(r.rows, names);

    const std::filesystem::path dir(cmd.output);
    write_plots(dir, r);
    r.seconds_total = seconds_since(start);
    write_csv(dir / "study.csv", r);
    write_json(dir / "study.json", r);
    write_contact_csv(dir / "contact_stability.csv", r);
    write_text_atomic(dir / "contact_effort.csv", effort_csv(r.contact_effort));
    write_report(dir / "report.md", r);
    if (r.auto_checked) write_text_atomic(dir / "auto.csv", auto_csv(r.auto_cases));
}

int run_study(const StudyCommand& cmd) {
    io::InterruptGuard guard; // Ctrl-C: every worker stops at its next poll; nothing is written
    const Clock::time_point start = Clock::now();
    Results r;
    r.quick = cmd.quick;
    r.threads = cmd.threads > 0
                    ? cmd.threads
                    : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    r.timing = cmd.quick ? TimingSettings{3, 1e-3} : TimingSettings{5, 2e-3};
    try {
        io::ensure_writable_directory(cmd.output);
    } catch (const io::FileError& e) {
        throw io::BadInput(e.what()); // before the run: the output folder cannot be used
    }
    if (!cmd.peers.empty()) r.contact_effort = read_peer_points(cmd.peers); // bad input: now
    try {
        measure_and_write(r, cmd, start);
    } catch (const io::Interrupted&) {
        throw;                          // 128 + the signal, nothing written
    } catch (const std::exception& e) { // a failed run (exit 1), named as the study's
        throw std::runtime_error(std::string("study: ") + e.what());
    }
    if (!cmd.quiet) print_summary(r, cmd.output);
    return kOk;
}

} // namespace

Subcommand add_study_command(CLI::App& app) {
    auto cmd = std::make_shared<StudyCommand>();
    CLI::App* st = app.add_subcommand(
        "study",
        "work-precision study of every integrator, and the stability map (report + plots)");
    st->add_flag("--quick", cmd->quick, "small grid, under a minute on 2 cores (what CI runs)");
    st->add_option("-o,--output", cmd->output, "output folder (default: study)");
    st->add_option("--threads", cmd->threads, "worker threads (default: one per hardware thread)")
        ->check(CLI::PositiveNumber);
    st->add_flag("-q,--quiet", cmd->quiet, "no progress and no summary");
    st->add_option("--peers", cmd->peers,
                   "the peer benchmark's CSV (scripts/bench-peers.sh: bench/results/<machine>/"
                   "peers.csv): ODE's points in the contacts' work-precision view");
    st->add_flag("--auto", cmd->auto_check,
                 "also check integrator \"auto\" against the exact answers at tolerances 1e-2 "
                 "to 1e-8: its estimate, whether it met them, its cost against the grid's "
                 "cheapest (report.md's last section, auto.csv)");
    return {[st] { return st->parsed(); }, [cmd] { return run_study(*cmd); }};
}

} // namespace tumble::app
