// gnuplot was chosen over Tumble's own renderer for figures: log axes, tick labels, legends and
// text are what a plotting program already does well, and the renderer has no text or 2D layer
// (issue 6 allows either). gnuplot-nox is a small, long-maintained Debian package without X; its
// pngcairo terminal draws anti-aliased PNGs with the DejaVu fonts, its svg terminal vector figures.
#include "app/gnuplot/gnuplot.h"

#include "io/atomic_file.h"

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/wait.h>

namespace tumble::app::gnuplot {
namespace {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

bool is_svg(const fs::path& figure) {
    return figure.extension() == ".svg";
}

std::string terminal(const GnuplotFigure& f) {
    const std::string size = std::to_string(f.width) + "," + std::to_string(f.height);
    if (is_svg(f.figure))
        return "set terminal svg size " + size +
               " fixed enhanced font \"DejaVu Sans,10\" background \"white\"\n";
    return "set terminal pngcairo size " + size + " font \"DejaVu Sans,10\"\n";
}

std::string script_text(const GnuplotFigure& f, const fs::path& script) {
    std::string s = "# drawn by `" + f.made_by + "`; redraw with: gnuplot " +
                    script.filename().string() + "\n" + terminal(f);
    s += "if (!exists(\"out\")) out = " + gnuplot_quote(f.figure.filename().string()) + "\n";
    for (const GnuplotData& d : f.data)
        s += "if (!exists(\"" + d.variable + "\")) " + d.variable + " = " +
             gnuplot_quote(d.file.filename().string()) + "\n";
    return s + "set output out\n" + f.body;
}

// Writes `text` to the file's temporary name; a failure (a full disk) names the figure it is for.
void write_whole(const io::AtomicFile& file, const std::string& text, const fs::path& figure) {
    std::FILE* out = std::fopen(file.temp_path().c_str(), "wb");
    int error = out ? 0 : errno;
    if (out && std::fwrite(text.data(), 1, text.size(), out) != text.size()) error = errno;
    if (out && std::fclose(out) != 0 && error == 0) error = errno;
    if (error != 0)
        throw io::FileError("cannot write '" + file.final_path().string() + "' (for '" +
                            figure.string() + "'): " + std::strerror(error));
}

// Runs `command` with its standard error joined to its output; returns (exit status, output).
std::pair<int, std::string> run(const std::string& command) {
    std::FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p) return {-1, "cannot start a shell"};
    std::string text;
    std::array<char, 4096> buf;
    for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), p)) > 0;)
        text.append(buf.data(), n);
    return {pclose(p), text};
}

} // namespace

std::string gnuplot_version() {
    auto [status, line] = run("gnuplot --version");
    if (status != 0 || !line.starts_with("gnuplot"))
        throw PlotError("gnuplot not found: Tumble draws its figures with gnuplot; install the "
                        "Debian package gnuplot-nox (scripts/setup.sh does)");
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    return line;
}

std::string gnuplot_quote(const std::string& text) {
    std::string out = "'"; // single quotes take no escapes; a quote inside is doubled
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

bool is_figure_name(const fs::path& figure) {
    return figure.extension() == ".png" || figure.extension() == ".svg";
}

void draw_with_gnuplot(const GnuplotFigure& f) {
    if (!f.figure.parent_path().empty()) io::ensure_writable_directory(f.figure.parent_path());
    const fs::path script = fs::path(f.figure).replace_extension(".gp");
    std::vector<std::unique_ptr<io::AtomicFile>> data;
    std::string variables; // -e 'name="temporary path"' for each input and the output
    for (const GnuplotData& d : f.data) {
        data.push_back(std::make_unique<io::AtomicFile>(d.file));
        write_whole(*data.back(), d.text, f.figure);
        variables += " -e " + shell_quote(d.variable + "=" +
                                          gnuplot_quote(data.back()->temp_path().string()));
    }
    io::AtomicFile script_file(script), figure(f.figure);
    write_whole(script_file, script_text(f, script), f.figure);
    variables += " -e " + shell_quote("out=" + gnuplot_quote(figure.temp_path().string()));
    const auto [status, messages] =
        run("gnuplot" + variables + " " + shell_quote(script_file.temp_path().string()));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw PlotError("gnuplot could not draw '" + f.figure.string() + "' from " +
                        script.string() + ":\n" + messages);
    for (const auto& d : data) d->commit();
    script_file.commit();
    figure.commit(); // last: a figure on disk always has its script and data beside it
}

} // namespace tumble::app::gnuplot
