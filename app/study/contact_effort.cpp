#include "app/study/contact_effort.h"
#include "app/gnuplot/gnuplot.h"
#include "app/study/runner.h"
#include "io/bad_input.h"
#include "physics/build.h"
#include "physics/scenes/contact_scenes.h"
#include "physics/scenes/sphere_rain.h"
#include "physics/step.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

namespace tumble::app::study {
namespace {

struct Setting {
    std::string name;
    double tolerance; // on demand; 0: fixed
    int substeps, iterations, relax;
};

std::vector<Setting> settings() {
    std::vector<Setting> out;
    for (double t : {1e-3, 3e-4, 1e-4, 3e-5, 1e-5}) {
        char name[48];
        std::snprintf(name, sizeof name, "tolerance %g mm", 1e3 * t);
        out.push_back({name, t, 0, 0, 0});
    }
    out.push_back({"480x1", 0.0, 2, 1, 1});
    out.push_back({"1440x3", 0.0, 6, 3, 2});
    return out;
}

scenes::Scene scene_for(const std::string& name, const Setting& s) {
    scenes::Scene scene =
        name == "rain" ? scenes::sphere_rain(10, true) : scenes::box_stack(10, 0.2, 1.0 / 240.0);
    if (name == "stack") scene.duration = 10.0;
    physics::ContactSettings& c = scene.world.contact;
    if (s.tolerance > 0.0) c.tolerance = s.tolerance;
    c.substeps = s.substeps, c.iterations = s.iterations;
    if (s.relax > 0) c.relax_iterations = s.relax;
    return scene;
}

// One run: its CPU time per step, and (when `measure`) its precision and effort.
double run_once(const std::string& name, const Setting& s, bool measure, EffortPoint& p) {
    const scenes::Scene scene = scene_for(name, s);
    const physics::Model model = physics::build_model(scene.world, scene.bodies);
    physics::State state = physics::initial_state(model, scene.bodies);
    const std::vector<physics::Vec3> start = state.x;
    physics::StepWorkspace ws(1);
    const auto steps = static_cast<long long>(std::llround(scene.duration / scene.world.dt));
    double drift = 0.0, point_sweeps = 0.0, points = 0.0, body_substeps = 0.0, bodies = 0.0;
    double seconds = 0.0;
    for (long long k = 0; k < steps; ++k) {
        const double t0 = thread_seconds();
        physics::step(model, state, ws);
        seconds += thread_seconds() - t0;
        if (!measure) continue;
        const physics::ContactStats& st = ws.contacts.stats();
        point_sweeps += st.effort.point_sweeps, points += st.points;
        body_substeps += st.effort.body_substeps, bodies += st.effort.bodies;
        if (name == "stack")
            for (std::size_t i = 1; i < state.x.size(); ++i) {
                const physics::Vec3 d = state.x[i] - start[i];
                drift = std::max({drift, d.head<2>().norm(), -d.z()});
            }
    }
    if (measure) {
        p.error_mm = 1e3 * (name == "rain" ? scenes::judge_rain(state).max_penetration : drift);
        p.sweeps_per_point = points > 0 ? point_sweeps / points : 0.0;
        p.substeps_per_body = bodies > 0 ? body_substeps / bodies : 0.0;
    }
    return 1e6 * seconds / steps;
}

std::string effort_number(double v, const char* format = "%.3g") {
    char text[32];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

} // namespace

std::vector<EffortPoint> contact_effort_study(int repetitions, int threads) {
    const std::vector<Setting> list = settings();
    std::vector<EffortPoint> points;
    for (const char* scene : {"rain", "stack"})
        for (const Setting& s : list)
            points.push_back({scene, s.name, s.tolerance, s.substeps, s.iterations});
    parallel_for(static_cast<int>(points.size()), threads, [&](int i) {
        EffortPoint& p = points[i];
        const Setting& s = list[i % list.size()];
        std::vector<double> times;
        for (int r = 0; r < std::max(1, repetitions); ++r)
            times.push_back(run_once(p.scene, s, r == 0, p));
        std::sort(times.begin(), times.end());
        p.us_per_step = times[times.size() / 2];
    });
    return points;
}

std::vector<EffortPoint> read_peer_points(const std::filesystem::path& csv) {
    std::ifstream in(csv);
    if (!in) throw io::BadInput(csv.string() + ": cannot read the peer benchmark's CSV");
    std::vector<EffortPoint> points;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::vector<std::string> cells;
        std::stringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
        if (number == 1) {
            if (cells.size() < 5 || cells[0] != "scene" || cells[2] != "steps_per_s" ||
                cells[4] != "max_penetration_mm")
                throw io::BadInput(csv.string() + ":1: expected the header of peers.csv "
                                                  "(scene,case,steps_per_s,x_ode,"
                                                  "max_penetration_mm,...), written by "
                                                  "scripts/bench-peers.sh");
            continue;
        }
        if (cells.size() < 8 || cells[1] != "ode") continue;
        if (cells[0] != "rain1000" && cells[0] != "stack10") continue;
        try {
            const double rate = std::stod(cells[2]);
            EffortPoint p{cells[0] == "rain1000" ? "rain" : "stack", "ODE (peer benchmark)"};
            p.us_per_step = 1e6 / rate;
            // The stack's precision is its drift or sinking, as here (columns 7 and 8).
            p.error_mm = p.scene == "rain" ? std::stod(cells[4])
                                           : std::max(std::stod(cells[6]), std::stod(cells[7]));
            p.peer = true;
            points.push_back(p);
        } catch (const std::exception&) {
            throw io::BadInput(csv.string() + ":" + std::to_string(number) +
                               ": expected numbers in the steps_per_s and penetration columns");
        }
    }
    return points;
}

std::string effort_csv(const std::vector<EffortPoint>& points) {
    std::string out = "scene,setting,tolerance_m,substeps,iterations,us_per_step,error_mm,"
                      "sweeps_per_point,substeps_per_body,peer\n";
    for (const EffortPoint& p : points)
        out += p.scene + ',' + p.setting + ',' + effort_number(p.tolerance) + ',' +
               std::to_string(p.substeps) + ',' + std::to_string(p.iterations) + ',' +
               effort_number(p.us_per_step, "%.4g") + ',' + effort_number(p.error_mm, "%.4g") + ',' +
               effort_number(p.sweeps_per_point) + ',' + effort_number(p.substeps_per_body) + ',' +
               (p.peer ? "1" : "0") + '\n';
    return out;
}

std::string effort_markdown(const std::vector<EffortPoint>& points) {
    std::string md =
        "## Contacts: what each effort setting buys\n\n"
        "Cost per step against precision on two scenes (app/study/contact_effort.h): the shifted "
        "sphere rain (N = 1000, 5 s; precision: the deepest overlap at the end) and a column of "
        "10 boxes (10 s; precision: the largest sideways drift or sinking of any box). Effort on "
        "demand follows the contact tolerance (`world.contact_tolerance`, `--contact-tolerance`; "
        "docs/contacts.md); 480x1 and 1440x3 are fixed settings (`world.substeps`, "
        "`world.iterations`). Timed by the thread's CPU clock, median of the repetitions. "
        "![contact effort](plots/contact-effort.png)\n\n";
    for (const char* scene : {"rain", "stack"}) {
        md += std::string("| ") + (std::string(scene) == "rain" ? "sphere rain" : "stack of 10") +
              " | us per step | " +
              (std::string(scene) == "rain" ? "overlap at the end, mm" : "drift or sink, mm") +
              " | sweeps per point per step | substeps per body |\n|---|---|---|---|---|\n";
        for (const EffortPoint& p : points) {
            if (p.scene != scene) continue;
            md += "| " + p.setting + " | " + effort_number(p.us_per_step, "%.4g") + " | " +
                  effort_number(p.error_mm, "%.3g") + " | " + (p.peer ? "-" : effort_number(p.sweeps_per_point)) +
                  " | " + (p.peer ? "-" : effort_number(p.substeps_per_body)) + " |\n";
        }
        md += "\n";
    }
    return md;
}

void effort_plot(const std::filesystem::path& dir, const std::vector<EffortPoint>& points) {
    std::ostringstream o;
    o << "set logscale xy\nset format x \"10^{%L}\"\nset grid\nset key outside right top\n"
      << "set multiplot layout 1,2 title \"contacts: cost per step against precision\"\n";
    for (const char* scene : {"rain", "stack"}) {
        const bool rain = std::string(scene) == "rain";
        o << "set title \"" << (rain ? "sphere rain, N = 1000" : "column of 10 boxes") << "\"\n"
          << "set xlabel \"" << (rain ? "deepest overlap at the end, mm" : "drift or sink, mm")
          << "\"\nset ylabel \"us per step\"\n";
        std::string plot;
        for (const bool peer : {false, true}) {
            std::string block = std::string("$") + scene + (peer ? "_peer" : "");
            o << block << " << EOD\n";
            int rows = 0;
            for (const EffortPoint& p : points)
                if (p.scene == scene && p.peer == peer) {
                    o << effort_number(std::max(p.error_mm, 1e-6), "%.6g") << ' '
                      << effort_number(p.us_per_step, "%.6g") << " \"" << p.setting << "\"\n";
                    ++rows;
                }
            o << "EOD\n";
            if (rows == 0) continue;
            plot += std::string(plot.empty() ? "plot " : ", ") + block + " using 1:2 with points " +
                    (peer ? "pt 5 ps 1.5 title \"ODE (peer)\"" : "pt 7 title \"Tumble\"") + ", " +
                    block + " using 1:2:3 with labels offset 1,0.6 font \",8\" notitle";
        }
        o << plot << "\n";
    }
    o << "unset multiplot\n";
    gnuplot::draw_with_gnuplot(
        {dir / "plots" / "contact-effort.png", "tumble study", 1200, 520, o.str(), {}});
}

} // namespace tumble::app::study
