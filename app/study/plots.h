#pragma once
// The study's PNG plots, drawn by gnuplot (app/gnuplot/gnuplot.h) on generated scripts with the
// data inline. Each plot keeps its script beside the PNG (plots/<name>.gp), so a user can restyle
// and redraw it with `gnuplot <name>.gp`.
#include "app/gnuplot/gnuplot.h"
#include "app/study/report.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tumble::app::study {

// PNG paths relative to the output folder, as the report links them.
std::string work_precision_plot(const std::string& problem);
std::string error_vs_dt_plot(const std::string& problem);
inline const char* energy_plot() {
    return "plots/energy.png";
}
inline const char* stability_plot() {
    return "plots/stability.png";
}
inline const char* contact_stability_plot() {
    return "plots/contact-stability.png";
}

// Draws every plot into dir/plots/. Throws gnuplot::PlotError when gnuplot fails (its message
// included).
void write_plots(const std::filesystem::path& dir, const Results& r);

// Errors below this are drawn at it (log axes cannot show 0).
inline constexpr double kPlotFloor = 1e-16;

} // namespace tumble::app::study
