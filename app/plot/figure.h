#pragma once
// A figure of `tumble plot`: the series as a data file, a gnuplot script that draws them and the
// figure itself, side by side (fig.png, fig.gp, fig.dat), through the study's gnuplot route
// (app/gnuplot/gnuplot.h): nothing is half-written, and `gnuplot fig.gp` redraws it.
//
// The data file holds one block per series, in the order of the legend, blocks separated by two
// blank lines (gnuplot's `index`):
//   # euler: book: rotational
//   # t value
//   0 0.123...
#include "app/plot/series.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tumble::app::plot {

struct FigureLabels {
    std::string title;  // "rotational kinetic energy of book"
    std::string ylabel; // "rotational kinetic energy, J"
};

// The data file's text (%.17g: the values as computed).
std::string data_text(const std::vector<Series>& series);

// <figure stem>.dat beside the figure.
std::filesystem::path data_path(const std::filesystem::path& figure);

// Draws `figure` (.png or .svg, width x height pixels). Throws gnuplot::PlotError if gnuplot fails.
void draw_figure(const std::filesystem::path& figure, const std::vector<Series>& series,
                 const FigureLabels& labels, int width, int height);

} // namespace tumble::app::plot
