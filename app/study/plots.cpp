// The study's figures: work against precision, error against step, energy, stability maps.
#include "app/study/plots.h"
#include "physics/integrator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tumble::app::study {
namespace {

namespace fs = std::filesystem;

// Draws dir/plots/<name>.png from `body`, its script kept beside it (app/gnuplot/gnuplot.h).
void draw(const fs::path& dir, const std::string& name, const std::string& body) {
    gnuplot::draw_with_gnuplot(
        {dir / "plots" / (name + ".png"), "tumble study", 900, 560, body, {}});
}

// A value for a log axis, at least kPlotFloor (0 has no place on it).
std::string log_axis_value(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", std::max(v, kPlotFloor));
    return buf;
}

std::string fixed2(double v) {
    if (std::isnan(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

const char* kLogAxes = "set logscale xy\nset format x \"10^{%L}\"\nset format y \"10^{%L}\"\n"
                       "set grid\nset key outside right top\n";

// One datablock per integrator with at least one point; returns the plot command.
template <class Points>
std::string series(std::ostringstream& o, const std::vector<std::string>& titles, Points points,
                   bool markers = true) {
    std::string plot;
    for (std::size_t i = 0; i < titles.size(); ++i) {
        const std::vector<std::pair<double, double>> xy = points(i);
        if (xy.empty()) continue;
        o << "$d" << i << " << EOD\n";
        for (const auto& [x, y] : xy) o << log_axis_value(x) << ' ' << log_axis_value(y) << '\n';
        o << "EOD\n";
        plot += std::string(plot.empty() ? "plot " : ", \\\n     ") + "$d" + std::to_string(i) +
                " using 1:2 with " +
                (markers ? "linespoints lw 1.5 pt " + std::to_string(i + 1)
                         : std::string("lines lw 1.5")) +
                " title \"" + titles[i] + "\" noenhanced";
    }
    return plot + "\n";
}

// (x, headline error) of one (problem, integrator), diverged rows left out.
std::vector<std::pair<double, double>> rows_xy(const Results& r, const std::string& problem,
                                               const std::string& integrator, bool cost) {
    std::vector<std::pair<double, double>> xy;
    for (const Row& row : r.rows)
        if (row.problem == problem && row.integrator == integrator && !row.diverged)
            xy.emplace_back(cost ? row.cost_s : row.dt, headline_error(row));
    std::sort(xy.begin(), xy.end());
    return xy;
}

void problem_plots(const fs::path& dir, const Results& r, const std::string& problem) {
    const std::vector<std::string> names = integrator_names();
    bool contacts = false;
    for (const Row& row : r.rows) contacts |= row.problem == problem && row.contacts;
    const char* ylabel = contacts ? "set ylabel \"position error, max over [0, T], m\"\n"
                                  : "set ylabel \"orientation error, max over [0, T], rad\"\n";
    std::ostringstream wp;
    wp << kLogAxes << "set title \"" << problem
       << ": work against precision\"\nset xlabel \"cost: measured time to simulate [0, T], s\"\n"
       << ylabel;
    wp << series(wp, names, [&](std::size_t i) { return rows_xy(r, problem, names[i], true); });
    draw(dir, fs::path(work_precision_plot(problem)).stem().string(), wp.str());

    std::vector<std::string> titles;
    for (const std::string& n : names) {
        std::string t = n;
        for (const OrderFit& f : r.orders)
            if (f.problem == problem && f.integrator == n) t += " (p = " + fixed2(f.measured) + ")";
        titles.push_back(t);
    }
    std::ostringstream dt;
    dt << kLogAxes << "set title \"" << problem
       << ": error against step (p: fitted order)\"\nset xlabel \"time step h, s\"\n"
       << ylabel;
    dt << series(dt, titles, [&](std::size_t i) { return rows_xy(r, problem, names[i], false); });
    draw(dir, fs::path(error_vs_dt_plot(problem)).stem().string(), dt.str());
}

void energy_plots(const fs::path& dir, const Results& r) {
    std::vector<std::string> titles;
    for (const EnergyTrace& t : r.energy)
        titles.push_back(t.integrator + (t.diverged ? " (diverged)" : ""));
    std::ostringstream o;
    o << "set logscale y\nset format y \"10^{%L}\"\nset grid\nset key outside right top\n"
      << "set title \"" << r.energy_problem << ": energy error at h = " << r.energy_dt
      << " s (values below 1e-16 drawn at 1e-16)\"\nset xlabel \"t, s\"\n"
         "set ylabel \"|E(t) - E(0)| / E(0)\"\n";
    o << series(
        o, titles, [&](std::size_t i) { return r.energy[i].points; }, false);
    draw(dir, "energy", o.str());
}

void stability_plots(const fs::path& dir, const Results& r) {
    const std::vector<std::string> names = integrator_names();
    std::ostringstream o;
    o << "set multiplot layout 1,2 title \"largest h|w| keeping energy within 10% over 10000 "
         "steps (k = 1: the sphere)\"\n"
      << kLogAxes << "set key off\nset xlabel \"k\"\nset ylabel \"h|w|\"\n";
    for (const std::string family : {"plate", "rod"}) {
        o << "set title \""
          << (family == std::string("plate") ? "flat plates 1 : k : 1+k" : "thin rods 1/k : 1 : 1")
          << "\"\n";
        if (family == std::string("rod")) o << "set key outside right top\n";
        o << series(o, names, [&](std::size_t i) {
            std::vector<std::pair<double, double>> xy;
            for (const StabilityResult& s : r.stability)
                if (s.integrator == names[i] &&
                    (s.inertia.family == family || s.inertia.family == "sphere"))
                    xy.emplace_back(s.inertia.k, s.h_w);
            std::sort(xy.begin(), xy.end());
            return xy;
        });
    }
    o << "unset multiplot\n";
    draw(dir, "stability", o.str());
}

// The contact map for the default integrator: the largest step of each case, one series per
// substep setting, against the default step (a dashed line).
void contact_plots(const fs::path& dir, const Results& r) {
    const std::vector<ContactCase> cases = contact_cases();
    std::vector<int> subs;
    for (const ContactStabilityResult& c : r.contact_stability)
        if (std::find(subs.begin(), subs.end(), c.substeps) == subs.end())
            subs.push_back(c.substeps);
    std::vector<std::string> titles;
    for (int n : subs)
        titles.push_back(n == 0 ? std::string("rk4, default substeps")
                                : "rk4, " + std::to_string(n) + " substeps");
    std::ostringstream o;
    o << "set logscale y\nset format y \"10^{%L}\"\nset grid\nset key outside right top\n"
      << "set title \"contacts: largest step at which each case holds (dashed: h = 1/240 s)\"\n"
      << "set ylabel \"h, s\"\nset xrange [-0.5:" << cases.size() - 0.5
      << "]\nset xtics rotate by 35 right (";
    for (std::size_t i = 0; i < cases.size(); ++i)
        o << (i ? ", " : "") << '"' << cases[i].label << "\" " << i;
    o << ")\nset arrow from -0.5," << 1.0 / 240.0 << " to " << cases.size() - 0.5 << ','
      << 1.0 / 240.0 << " nohead dt 2 lc rgb \"gray40\"\n";
    o << series(o, titles, [&](std::size_t k) {
        std::vector<std::pair<double, double>> xy;
        for (std::size_t i = 0; i < cases.size(); ++i)
            for (const ContactStabilityResult& c : r.contact_stability)
                if (c.integrator == "rk4" && c.substeps == subs[k] && c.c.label == cases[i].label)
                    xy.emplace_back(double(i), c.dt);
        return xy;
    });
    draw(dir, "contact-stability", o.str());
}

} // namespace

std::string work_precision_plot(const std::string& problem) {
    return "plots/work-precision-" + problem + ".png";
}

std::string error_vs_dt_plot(const std::string& problem) {
    return "plots/error-vs-dt-" + problem + ".png";
}

void write_plots(const fs::path& dir, const Results& r) {
    std::vector<std::string> seen;
    for (const Row& row : r.rows)
        if (std::find(seen.begin(), seen.end(), row.problem) == seen.end()) {
            seen.push_back(row.problem);
            problem_plots(dir, r, row.problem);
        }
    energy_plots(dir, r);
    stability_plots(dir, r);
    if (!r.contact_stability.empty()) contact_plots(dir, r);
    if (!r.contact_effort.empty()) effort_plot(dir, r.contact_effort);
}

} // namespace tumble::app::study
