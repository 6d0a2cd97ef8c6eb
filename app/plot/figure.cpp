#include "app/plot/figure.h"

#include "app/gnuplot/gnuplot.h"

#include <cstdio>

namespace tumble::app::plot {
namespace {

using gnuplot::gnuplot_quote;

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string plot_commands(const std::vector<Series>& series, const FigureLabels& labels) {
    std::string s = "set title " + gnuplot_quote(labels.title) + " noenhanced\n" +
                    "set xlabel 't, s'\nset ylabel " + gnuplot_quote(labels.ylabel) +
                    " noenhanced\nset grid\nset key outside right top noenhanced\n" +
                    "set format y '%g'\n";
    for (std::size_t i = 0; i < series.size(); ++i)
        s += std::string(i == 0 ? "plot " : ", \\\n     ") + "data index " + std::to_string(i) +
             " using 1:2 with lines lw 1.5 title " + gnuplot_quote(series[i].title);
    return s + "\n";
}

} // namespace

std::string data_text(const std::vector<Series>& series) {
    std::string s;
    for (std::size_t i = 0; i < series.size(); ++i) {
        if (i > 0) s += "\n\n";
        s += "# " + series[i].title + "\n# t value\n";
        for (const auto& [t, v] : series[i].points) s += number(t) + " " + number(v) + "\n";
    }
    return s;
}

std::filesystem::path data_path(const std::filesystem::path& figure) {
    return std::filesystem::path(figure).replace_extension(".dat");
}

void draw_figure(const std::filesystem::path& figure, const std::vector<Series>& series,
                 const FigureLabels& labels, int width, int height) {
    gnuplot::GnuplotFigure f;
    f.figure = figure;
    f.made_by = "tumble plot";
    f.width = width;
    f.height = height;
    f.body = plot_commands(series, labels);
    f.data.push_back({"data", data_path(figure), data_text(series)});
    gnuplot::draw_with_gnuplot(f);
}

} // namespace tumble::app::plot
