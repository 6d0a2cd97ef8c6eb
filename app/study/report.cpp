// study.csv and study.json (every row of the study), and the machine and build descriptions.
#include "app/study/report.h"
#include "io/atomic_file.h"
#include "physics/integrator.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#ifndef TUMBLE_BUILD_TYPE
#define TUMBLE_BUILD_TYPE "unknown"
#endif
#ifndef TUMBLE_CXX_FLAGS
#define TUMBLE_CXX_FLAGS "unknown"
#endif

namespace tumble::app::study {

std::string sci(double v, int digits) {
    if (std::isnan(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*e", digits, v);
    return buf;
}

std::vector<std::string> integrator_names() {
    std::vector<std::string> names;
    for (const physics::IntegratorInfo& info : physics::integrators())
        names.emplace_back(info.name);
    return names;
}

std::string describe_machine() {
    std::ifstream in("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " logical cores";
}

std::string describe_build() {
    return std::string("GCC ") + __VERSION__ + ", " + TUMBLE_BUILD_TYPE +
           ", flags: " + TUMBLE_CXX_FLAGS;
}

void write_text_atomic(const std::filesystem::path& file, const std::string& text) {
    io::AtomicFile f(file);
    {
        std::ofstream out(f.temp_path(), std::ios::binary);
        out << text;
        if (!out.flush()) throw io::FileError("cannot write " + file.string());
    }
    f.commit();
}

namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

void errors_csv(std::ostringstream& o, const Errors& e) {
    o << ',' << num(e.position) << ',' << num(e.orientation) << ',' << num(e.angular_velocity)
      << ',' << num(e.energy) << ',' << num(e.momentum);
}

nlohmann::json errors_json(const Errors& e) {
    return {{"position", e.position},
            {"orientation", e.orientation},
            {"angular_velocity", e.angular_velocity},
            {"energy", e.energy},
            {"momentum", e.momentum}};
}

} // namespace

void write_csv(const std::filesystem::path& file, const Results& r) {
    std::ostringstream o;
    o << "problem,integrator,order,bodies,dt,steps,h_w,diverged,diverged_body,diverged_step,"
         "diverged_quantity,pos_end,ori_end,w_end,energy_end,momentum_end,pos_max,ori_max,w_max,"
         "energy_max,momentum_max,ns_per_body_step,steps_per_second,cost_s,repetitions\n";
    for (const Row& row : r.rows) {
        o << row.problem << ',' << row.integrator << ',' << row.order << ',' << row.bodies << ','
          << num(row.dt) << ',' << row.steps << ',' << num(row.h_w) << ',' << (row.diverged ? 1 : 0)
          << ',' << row.diverged_body << ',' << row.diverged_step << ',' << row.diverged_quantity;
        errors_csv(o, row.end);
        errors_csv(o, row.max);
        o << ',' << num(row.ns_per_body_step) << ',' << num(row.steps_per_second) << ','
          << num(row.cost_s) << ',' << row.repetitions << '\n';
    }
    write_text_atomic(file, o.str());
}

void write_json(const std::filesystem::path& file, const Results& r) {
    nlohmann::json j;
    j["quick"] = r.quick;
    j["threads"] = r.threads;
    j["machine"] = r.machine;
    j["build"] = r.build;
    j["plotter"] = r.plotter;
    j["samples"] = kSamples;
    j["timing"] = {{"repetitions", r.timing.repetitions},
                   {"min_rep_seconds", r.timing.min_rep_seconds}};
    j["seconds"] = {{"grid", r.seconds_grid},
                    {"stability", r.seconds_stability},
                    {"contacts", r.seconds_contacts},
                    {"total", r.seconds_total}};
    for (const Row& row : r.rows)
        j["rows"].push_back({{"problem", row.problem},
                             {"integrator", row.integrator},
                             {"order", row.order},
                             {"bodies", row.bodies},
                             {"dt", row.dt},
                             {"steps", row.steps},
                             {"h_w", row.h_w},
                             {"diverged", row.diverged},
                             {"diverged_body", row.diverged_body},
                             {"diverged_step", row.diverged_step},
                             {"diverged_quantity", row.diverged_quantity},
                             {"end", errors_json(row.end)},
                             {"max", errors_json(row.max)},
                             {"ns_per_body_step", row.ns_per_body_step},
                             {"steps_per_second", row.steps_per_second},
                             {"cost_s", row.cost_s},
                             {"repetitions", row.repetitions},
                             {"exact_here", row.exact_here}});
    j["skipped"] = nlohmann::json::array();
    for (const Skip& k : r.skipped)
        j["skipped"].push_back(
            {{"problem", k.problem}, {"integrator", k.integrator}, {"reason", k.reason}});
    for (const OrderFit& f : r.orders)
        j["orders"].push_back({{"problem", f.problem},
                               {"integrator", f.integrator},
                               {"theory", f.theory},
                               {"measured", f.measured}, // NaN -> null
                               {"points", f.points}});
    for (const Recommendation& rec : r.recommendations) {
        nlohmann::json e = {{"problem", rec.problem}, {"target", rec.target}};
        if (rec.row)
            e.update({{"integrator", rec.row->integrator},
                      {"dt", rec.row->dt},
                      {"steps", rec.row->steps},
                      {"orientation_error", rec.row->max.orientation},
                      {"error", headline_error(*rec.row)},
                      {"cost_s", rec.row->cost_s},
                      {"ns_per_body_step", rec.row->ns_per_body_step}});
        else
            e["integrator"] = nullptr;
        j["recommendations"].push_back(e);
    }
    for (const StabilityResult& s : r.stability)
        j["stability"].push_back(
            {{"family", s.inertia.family},
             {"k", s.inertia.k},
             {"moments", {s.inertia.moments.x(), s.inertia.moments.y(), s.inertia.moments.z()}},
             {"integrator", s.integrator},
             {"h_w", s.h_w},
             {"below_range", s.below_range},
             {"above_range", s.above_range},
             {"evaluations", s.evaluations}});
    for (const ContactStabilityResult& c : r.contact_stability)
        j["contact_stability"].push_back({{"case", c.c.label},
                                          {"family", c.c.family},
                                          {"parameter", c.c.parameter},
                                          {"integrator", c.integrator},
                                          {"substeps", c.substeps},
                                          {"dt", c.dt},
                                          {"holds_default", c.holds_default},
                                          {"below_range", c.below_range},
                                          {"above_range", c.above_range},
                                          {"evaluations", c.evaluations}});
    write_text_atomic(file, j.dump(1) + "\n");
}

void write_contact_csv(const std::filesystem::path& file, const Results& r) {
    std::ostringstream o;
    o << "case,family,parameter,integrator,substeps,dt,holds_default,below_range,above_range,"
         "evaluations\n";
    for (const ContactStabilityResult& c : r.contact_stability)
        o << c.c.label << ',' << c.c.family << ',' << num(c.c.parameter) << ',' << c.integrator
          << ',' << c.substeps << ',' << num(c.dt) << ',' << c.holds_default << ',' << c.below_range
          << ',' << c.above_range << ',' << c.evaluations << '\n';
    write_text_atomic(file, o.str());
}

} // namespace tumble::app::study
