#pragma once
// The study's outputs: study.csv and study.json (every row), report.md (the Markdown report, ending
// with the recommendation table) and, through study_plots.h, the PNG plots it links to.
#include "app/study/analysis.h"
#include "app/study/auto_check.h"
#include "app/study/contact_effort.h"
#include "app/study/contact_stability.h"
#include "app/study/runner.h"
#include "app/study/stability.h"
#include "app/study/study.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tumble::app::study {

struct Results {
    bool quick = false;
    int threads = 1;
    TimingSettings timing;
    std::vector<Row> rows;
    std::vector<Skip> skipped; // pairs not run (`exact` on problems with torques), with the reason
    std::vector<OrderFit> orders;
    std::vector<Recommendation> recommendations;
    std::vector<StabilityResult> stability;
    std::vector<ContactStabilityResult> contact_stability;
    std::vector<EffortPoint> contact_effort; // the contacts' work-precision (contact_effort.h)
    std::string energy_problem;              // the problem and step of the energy-against-time plot
    double energy_dt = 0.0, energy_t_end = 0.0;
    std::vector<EnergyTrace> energy;
    bool auto_checked = false; // `--auto`: the plans of "auto" checked (auto_check.h)
    std::vector<AutoCase> auto_cases;
    double seconds_grid = 0.0, seconds_stability = 0.0, seconds_contacts = 0.0;
    double seconds_effort = 0.0;
    double seconds_total = 0.0;
    std::string machine; // CPU model and core count (/proc/cpuinfo)
    std::string build;   // compiler, build type, flags
    std::string plotter; // gnuplot's version line
};

// Every integrator's name, in physics' order: the order of the report's tables and plots' lines.
std::vector<std::string> integrator_names();

// Machine and build descriptions for the report.
std::string describe_machine();
std::string describe_build();

// Each writes its file atomically (temporary name, then rename). Throws io::FileError.
void write_csv(const std::filesystem::path& file, const Results& r);
void write_json(const std::filesystem::path& file, const Results& r);
void write_report(const std::filesystem::path& file, const Results& r);
// contact_stability.csv: one row per (case, integrator, substeps) of the contact map.
void write_contact_csv(const std::filesystem::path& file, const Results& r);

// Writes `text` to `file` under a temporary name, then renames it into place.
void write_text_atomic(const std::filesystem::path& file, const std::string& text);

// "1.23e-04", or "-" for NaN: the report's number format.
std::string sci(double v, int digits = 2);

} // namespace tumble::app::study
