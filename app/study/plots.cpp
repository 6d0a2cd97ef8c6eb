// gnuplot was chosen over Tumble's own renderer for the plots: log axes, tick labels, legends and
// text are what a plotting program already does well, and the renderer has no text or 2D layer
// (issue 6 allows either). gnuplot-nox is a small, long-maintained Debian package without X; its
// pngcairo terminal draws anti-aliased PNGs with the DejaVu fonts.
#include "app/study/plots.h"
#include "io/atomic_file.h"
#include "physics/integrator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <sys/wait.h>

namespace tumble::app::study {
namespace {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string read_all(const fs::path& p) {
    std::FILE* f = std::fopen(p.c_str(), "rb");
    std::string s;
    if (!f) return s;
    std::array<char, 4096> buf;
    for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), f)) > 0;)
        s.append(buf.data(), n);
    std::fclose(f);
    return s;
}

// Writes dir/plots/<name>.gp and runs it; gnuplot draws to a temporary name that is renamed to
// <name>.png once complete.
void draw(const fs::path& dir, const std::string& name, const std::string& body) {
    const fs::path plots = dir / "plots";
    fs::create_directories(plots);
    const fs::path script = plots / (name + ".gp"), png = plots / (name + ".png");
    write_text_atomic(script, "# drawn by `tumble study`; redraw with: gnuplot " + name +
                                  ".gp\nset terminal pngcairo size 900,560 font \"DejaVu "
                                  "Sans,10\"\nif (!exists(\"out\")) out = \"" +
                                  name + ".png\"\nset output out\n" + body);
    io::AtomicFile out(png);
    const fs::path log = plots / ("." + name + ".log");
    const std::string cmd = "gnuplot -e " +
                            shell_quote("out=\"" + out.temp_path().string() + "\"") + " " +
                            shell_quote(script.string()) + " 2> " + shell_quote(log.string());
    const int status = std::system(cmd.c_str());
    const std::string messages = read_all(log);
    fs::remove(log);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw PlotError("gnuplot failed on " + script.string() + ":\n" + messages);
    out.commit();
}

std::string num(double v) {
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
        for (const auto& [x, y] : xy) o << num(x) << ' ' << num(y) << '\n';
        o << "EOD\n";
        plot += std::string(plot.empty() ? "plot " : ", \\\n     ") + "$d" + std::to_string(i) +
                " using 1:2 with " +
                (markers ? "linespoints lw 1.5 pt " + std::to_string(i + 1)
                         : std::string("lines lw 1.5")) +
                " title \"" + titles[i] + "\" noenhanced";
    }
    return plot + "\n";
}

std::vector<std::string> integrator_names() {
    std::vector<std::string> names;
    for (const physics::IntegratorInfo& info : physics::integrators())
        names.emplace_back(info.name);
    return names;
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

std::string gnuplot_version() {
    std::FILE* p = popen("gnuplot --version 2>/dev/null", "r");
    std::string line;
    if (p) {
        std::array<char, 256> buf;
        if (std::fgets(buf.data(), buf.size(), p)) line = buf.data();
        const int status = pclose(p);
        if (status != 0) line.clear();
    }
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    if (line.empty())
        throw PlotError("gnuplot not found: the study draws its plots with gnuplot; install the "
                        "Debian package gnuplot-nox (scripts/setup.sh does)");
    return line;
}

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
}

} // namespace tumble::app::study
