#pragma once
// Shared by the regression-suite tests (tests/app/suite_*_test.cpp): a scratch copy of the
// project's suite and goldens to break on purpose, and the breakages.
#include "render/png_io.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace tumble::test {

inline const std::filesystem::path kProjectGoldens =
    std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests/goldens";

// dir/goldens: a copy of tests/goldens (suite.json, images, trajectories, renderer record).
inline std::filesystem::path copy_goldens(const std::filesystem::path& dir) {
    const auto copy = dir / "goldens";
    std::filesystem::copy(kProjectGoldens, copy, std::filesystem::copy_options::recursive);
    return copy;
}

// Paints the square [x0, x0 + side) x [y0, y0 + side) of a PNG magenta.
inline void paint_square(const std::filesystem::path& png, int x0, int y0, int side) {
    render::Image img = render::read_png(png);
    for (int y = y0; y < y0 + side; ++y)
        for (int x = x0; x < x0 + side; ++x) {
            std::uint8_t* p = img.row(y) + 3 * x;
            p[0] = 255, p[1] = 0, p[2] = 255;
        }
    render::write_png(png, img);
}

// Rewrites the CSV at `path` field by field: `edit(fields)` may change the fields of each data
// row (split at commas; the files' quoted names hold no comma).
inline void edit_csv(const std::filesystem::path& path,
                     const std::function<void(std::vector<std::string>&)>& edit) {
    std::istringstream in(read_text(path));
    std::string out, line;
    for (bool header = true; std::getline(in, line); header = false) {
        if (!header) {
            std::vector<std::string> f;
            std::stringstream s(line);
            for (std::string x; std::getline(s, x, ',');) f.push_back(x);
            edit(f);
            line.clear();
            for (const std::string& x : f) line += (line.empty() ? "" : ",") + x;
        }
        out += line + "\n";
    }
    write_text(path, out);
}

inline std::string shifted(const std::string& number, double by) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", std::stod(number) + by);
    return buf;
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace tumble::test
