#pragma once
// The gnuplot route of Tumble's figures (`tumble study`'s plots and `tumble plot`): a generated
// script run by gnuplot (Debian's gnuplot-nox) as a subprocess, pngcairo for .png and svg for
// .svg. The script is kept beside the figure (<name>.gp) with the data files it reads, so a user
// can restyle and redraw it with `gnuplot <name>.gp` in that folder. Nothing is half-written: the
// figure, its script and its data are drawn under temporary names (io/atomic_file.h) and renamed
// into place only once gnuplot has succeeded.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace tumble::app::gnuplot {

struct PlotError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// gnuplot's version line ("gnuplot 5.4 patchlevel 4"). Throws PlotError when gnuplot cannot be
// run, naming the package to install.
std::string gnuplot_version();

// A file the script reads, written beside the figure. The script names it by the gnuplot variable
// `variable` (set to `file`'s name when the user runs the script, to the temporary copy while
// Tumble draws).
struct GnuplotData {
    std::string variable; // e.g. "data"
    std::filesystem::path file;
    std::string text;
};

struct GnuplotFigure {
    std::filesystem::path figure; // .png (pngcairo) or .svg (svg); the script: same stem, .gp
    std::string made_by;          // "tumble study", named in the script's first line
    int width = 900, height = 560;
    std::string body; // the commands after terminal and output are set; `out` names the figure
    std::vector<GnuplotData> data;
};

// A gnuplot string constant holding `text` as it is ('...', quotes doubled, no escapes).
std::string gnuplot_quote(const std::string& text);

// True for the figure names the route can draw (.png, .svg).
bool is_figure_name(const std::filesystem::path& figure);

// Writes the script and data and draws the figure. Throws PlotError (gnuplot's messages included)
// when gnuplot fails; io errors as io::AtomicFile throws them.
void draw_with_gnuplot(const GnuplotFigure& figure);

} // namespace tumble::app::gnuplot
