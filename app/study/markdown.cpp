// report.md: the study as a person reads it, ending with the recommendation table.
#include "app/study/auto_check.h"
#include "app/study/metrics.h"
#include "app/study/plots.h"
#include "app/study/report.h"
#include "physics/integrator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tumble::app::study {
namespace {

std::string fixed(double v, int digits) {
    if (std::isnan(v)) return "-";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string g3(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

bool is_skipped(const Results& r, const std::string& problem, const std::string& integrator) {
    for (const Skip& k : r.skipped)
        if (k.problem == problem && k.integrator == integrator) return true;
    return false;
}

void header(std::ostringstream& o, const Results& r) {
    o << "# Tumble work-precision study" << (r.quick ? " (quick)" : "") << "\n\n"
      << "Made by `tumble study" << (r.quick ? " --quick" : "") << " --threads " << r.threads
      << "` in " << fixed(r.seconds_total, 1) << " s (grid " << fixed(r.seconds_grid, 1)
      << " s, stability map " << fixed(r.seconds_stability, 1) << " s, contact map "
      << fixed(r.seconds_contacts, 1) << " s).\n\n"
      << "- Machine: " << r.machine << "\n- Build: " << r.build << "\n- Plots: " << r.plotter
      << " (Debian `gnuplot-nox`, pngcairo), run on generated scripts kept beside the PNGs.\n"
      << "- Every row is in `study.csv` and `study.json`; docs/study.md explains the method.\n\n"
      << "Errors are measured against the exact oracles (or a converged run) at " << kSamples
      << " evenly spaced times; *end* is t = T, *max* the largest of the samples. Orientation "
         "error: the angle of R_ref^T R (rad). Cost: the median over "
      << r.timing.repetitions
      << " repetitions of the stepping loop's thread CPU time (errors not measured while timing), "
         "per body-step, and the resulting time to simulate [0, T]"
      << (r.threads > 1 ? "; rows ran on " + std::to_string(r.threads) +
                              " threads at once, sharing caches and memory bandwidth"
                        : "")
      << ".\n\n";
}

void problems_table(std::ostringstream& o, bool quick) {
    o << "## Problems\n\n| problem | T, s | reference | h\\|w\\| at the coarsest step | "
         "description |\n|---|---|---|---|---|\n";
    for (const Problem& p : problems())
        o << "| " << p.name << " | " << g3(p.duration) << " | "
          << (p.reference == ReferenceKind::Exact      ? "exact"
              : p.reference == ReferenceKind::Analytic ? "closed form"
                                                       : "converged run")
          << " | " << g3(p.duration / double(step_counts(p, quick).front()) * largest_spin(p))
          << " | " << p.description << " |\n";
    o << "\n";
}

void orders_table(std::ostringstream& o, const Results& r, const std::vector<std::string>& probs) {
    o << "## Measured order of convergence\n\nSlope of log(orientation error, max over [0, T]; "
         "position error for the contact problems, whose theory is the contact stage's 1) "
         "against log(h), fitted over the steps whose error lies in ["
      << sci(kFitMinError, 0) << ", " << sci(kFitMaxError, 0)
      << "] rad; `-` where fewer than three steps do (the method is never asymptotic on the "
         "grid, or exact on the problem to round-off). `exact`: the method truncates nothing on "
         "the problem (the exact free flow on a problem without torques or contacts), so its "
         "errors are round-off, which grows with the number of steps, and no order is fitted. "
         "`skipped`: not run (below).\n\n| integrator | theory |";
    for (const std::string& p : probs) o << ' ' << p << " |";
    o << "\n|---|---|";
    for (std::size_t i = 0; i < probs.size(); ++i) o << "---|";
    o << '\n';
    for (const std::string& n : integrator_names()) {
        // The free body's order from the registry: a contact problem's fit carries the contact
        // stage's order (1), which the text above states once for all.
        const auto id = physics::integrator_from_name(n);
        const std::string theory =
            id ? physics::order_text(physics::integrator_info(*id).order) : "?";
        std::ostringstream cells;
        for (const std::string& p : probs) {
            std::string cell = is_skipped(r, p, n) ? "skipped" : "-";
            for (const OrderFit& f : r.orders)
                if (f.problem == p && f.integrator == n)
                    cell = f.theory == physics::kExactOrder ? "exact" : fixed(f.measured, 2);
            cells << ' ' << cell << " |";
        }
        o << "| " << n << " | " << theory << " |" << cells.str() << '\n';
    }
    o << "\n";
}

// For each integrator, the row whose h|w| is closest (in log) to 0.05.
void problem_section(std::ostringstream& o, const Results& r, const std::string& problem) {
    o << "## " << problem << "\n\n![work-precision](" << work_precision_plot(problem)
      << ")\n\n![error against step](" << error_vs_dt_plot(problem) << ")\n\n"
      << "At the step nearest h|w| = 0.05:\n\n| integrator | h, s | h\\|w\\| | orientation end "
         "| orientation max | energy max | momentum max | position max, m | ns/body-step | "
         "steps/s |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const std::string& n : integrator_names()) {
        const Row* best = nullptr;
        for (const Row& row : r.rows)
            if (row.problem == problem && row.integrator == n &&
                (!best ||
                 std::abs(std::log(row.h_w / 0.05)) < std::abs(std::log(best->h_w / 0.05))))
                best = &row;
        if (!best) continue;
        o << "| " << n << " | " << g3(best->dt) << " | " << g3(best->h_w) << " | "
          << (best->diverged ? "diverged" : sci(best->end.orientation)) << " | "
          << sci(best->max.orientation) << " | " << sci(best->max.energy) << " | "
          << sci(best->max.momentum) << " | " << sci(best->max.position) << " | "
          << fixed(best->ns_per_body_step, 0) << " | " << g3(best->steps_per_second) << " |\n";
    }
    o << "\n";
    for (const Skip& k : r.skipped)
        if (k.problem == problem) o << "Not run: `" << k.integrator << "`: " << k.reason << ".\n\n";
}

void divergences(std::ostringstream& o, const Results& r) {
    o << "## Divergences\n\nRuns stopped by the divergence check (a state became NaN or "
         "infinite), recorded as results:\n\n";
    int count = 0;
    for (const Row& row : r.rows) {
        if (!row.diverged) continue;
        if (count++ == 0)
            o << "| problem | integrator | h, s | h\\|w\\| | body | step | quantity |\n"
                 "|---|---|---|---|---|---|---|\n";
        o << "| " << row.problem << " | " << row.integrator << " | " << g3(row.dt) << " | "
          << g3(row.h_w) << " | " << row.diverged_body << " | " << row.diverged_step << " | "
          << row.diverged_quantity << " |\n";
    }
    if (count == 0) o << "None.\n";
    o << "\n";
}

void energy_section(std::ostringstream& o, const Results& r) {
    o << "## Energy against time\n\n"
      << r.energy_problem << " at h = " << g3(r.energy_dt) << " s for " << g3(r.energy_t_end)
      << " s.\n\n![energy](" << energy_plot()
      << ")\n\n| integrator | max \\|E - E0\\| / E0 | at the end |\n|---|---|---|\n";
    for (const EnergyTrace& t : r.energy) {
        double mx = 0.0;
        for (const auto& pt : t.points) mx = std::max(mx, pt.second);
        o << "| " << t.integrator << (t.diverged ? " (diverged)" : "") << " | " << sci(mx) << " | "
          << sci(t.points.back().second) << " |\n";
    }
    o << "\n";
}

std::string stability_cell(const StabilityResult& s) {
    if (s.below_range) return "< " + g3(kMinHw);
    if (s.above_range) return "> " + g3(kMaxHw);
    return g3(s.h_w);
}

void stability_section(std::ostringstream& o, const Results& r) {
    const std::vector<std::string> names = integrator_names();
    o << "## Stability map\n\nLargest h|w| at which a torque-free body tumbling with w = (1, 1, 1) "
         "/ sqrt(3) in its principal axes keeps |E - E0| <= 0.1 E0 at every one of "
      << kStabilitySteps << " steps, by doubling from " << g3(kMinHw) << " then bisection (ratio "
      << (r.quick ? "1.05" : "1.01") << "); capped at " << g3(kMaxHw) << ".\n\n![stability]("
      << stability_plot() << ")\n\n| moments |";
    for (const std::string& n : names) o << ' ' << n << " |";
    o << "\n|---|";
    for (std::size_t i = 0; i < names.size(); ++i) o << "---|";
    o << '\n';
    for (std::size_t i = 0; i < r.stability.size(); i += names.size()) {
        const InertiaCase& c = r.stability[i].inertia;
        o << "| " << c.family << ' ' << g3(c.moments.x()) << " : " << g3(c.moments.y()) << " : "
          << g3(c.moments.z()) << " |";
        for (std::size_t j = 0; j < names.size(); ++j)
            o << ' ' << stability_cell(r.stability[i + j]) << " |";
        o << '\n';
    }
    o << "\n";
}

std::string contact_cell(const ContactStabilityResult& c) {
    if (c.below_range) return "< " + g3(kMinContactDt);
    if (c.above_range) return ">= " + g3(c.dt);
    return g3(c.dt) + (c.holds_default ? "" : " **!**");
}

// One table: the cases down, the (integrator, substeps) settings across.
void contact_section(std::ostringstream& o, const Results& r) {
    if (r.contact_stability.empty()) return;
    std::vector<std::pair<std::string, int>> cols;
    for (const ContactStabilityResult& c : r.contact_stability) {
        const std::pair<std::string, int> key{c.integrator, c.substeps};
        if (std::find(cols.begin(), cols.end(), key) == cols.end()) cols.push_back(key);
    }
    o << "## Contact stability map\n\nLargest step h (s) at which each contact case holds, for "
         "each integrator and contact substep count (\"auto\": the default, the fewest substeps "
         "with h / n <= 1/480 s). From h = 1/240 s the step doubles while the case holds (up to "
      << g3(kMaxContactDt) << " s) or halves until it does (down to " << g3(kMinContactDt)
      << " s), then bisection (ratio " << (r.quick ? "1.25" : "1.05")
      << "). **!** marks a setting that fails at the default step 1/240 s; a case is inside "
         "its region at a given step when that step is at most the number shown.\n\n![contacts]("
      << contact_stability_plot() << ")\n\n| case | holds when |";
    for (const auto& [name, n] : cols)
        o << ' ' << name << ", " << (n == 0 ? std::string("auto") : std::to_string(n)) << " |";
    o << "\n|---|---|";
    for (std::size_t i = 0; i < cols.size(); ++i) o << "---|";
    o << '\n';
    for (std::size_t i = 0; i < r.contact_stability.size(); i += cols.size()) {
        const ContactCase& c = r.contact_stability[i].c;
        o << "| " << c.label << " | " << c.bound << " |";
        for (std::size_t j = 0; j < cols.size(); ++j)
            o << ' ' << contact_cell(r.contact_stability[i + j]) << " |";
        o << '\n';
    }
    o << "\n";
}

void recommendation_section(std::ostringstream& o, const Results& r) {
    o << "## Recommendation\n\nFor each target orientation error (position error, m, for the "
         "contact problems; the maximum over [0, T], T "
         "fixed per problem), the cheapest integrator and step that reach it, at that step and "
         "at every finer step of the same integrator, with the measured cost. \"coarsest tried\": "
         "the "
         "grid's largest step already reaches the target (a larger one might too).\n\n"
         "| problem | target, rad | integrator | h, s | h\\|w\\| | error, rad | cost of [0, T], "
         "ms | ns/body-step |\n|---|---|---|---|---|---|---|---|\n";
    for (const Recommendation& rec : r.recommendations) {
        o << "| " << rec.problem << " | " << sci(rec.target, 0) << " | ";
        if (!rec.row) {
            o << "not reached on the grid | | | | | |\n";
            continue;
        }
        // At the grid's coarsest step a larger step might reach the target too: say so.
        bool coarsest = false;
        for (const Problem& p : problems())
            if (p.name == rec.problem) coarsest = rec.row->steps == step_counts(p, r.quick).front();
        o << rec.row->integrator << " | " << g3(rec.row->dt)
          << (coarsest ? " (coarsest tried)" : "") << " | " << g3(rec.row->h_w) << " | "
          << sci(headline_error(*rec.row)) << " | " << g3(1e3 * rec.row->cost_s) << " | "
          << fixed(rec.row->ns_per_body_step, 0) << " |\n";
    }
}

} // namespace

void write_report(const std::filesystem::path& file, const Results& r) {
    std::vector<std::string> probs;
    for (const Row& row : r.rows)
        if (probs.empty() || probs.back() != row.problem) probs.push_back(row.problem);
    std::ostringstream o;
    header(o, r);
    problems_table(o, r.quick);
    orders_table(o, r, probs);
    for (const std::string& p : probs) problem_section(o, r, p);
    divergences(o, r);
    energy_section(o, r);
    stability_section(o, r);
    contact_section(o, r);
    if (!r.contact_effort.empty()) o << effort_markdown(r.contact_effort);
    recommendation_section(o, r);
    if (r.auto_checked) o << "\n" << auto_markdown(r.auto_cases);
    write_text_atomic(file, o.str());
}

} // namespace tumble::app::study
