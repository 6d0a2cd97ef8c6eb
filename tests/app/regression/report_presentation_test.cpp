// Issue 30, item 6: the HTML report of `tumble test` reads right. A suite of one scene is given
// goldens by --update, then made to fail a state check and an image check and to pass an image
// check that is not bit-identical, and its scene is edited. The report must put the state failure
// first, word the pass as a pass, say that the scene changed since its goldens were made, and
// draw plots whose titles fit, whose ticks are whole multiples of a nice step and whose tolerance
// band is at least 3 px thick.
#include "render/png_io.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

namespace tumble::test {
namespace {

const char* const kScene = R"({"format_version": 1, "title": "a spinning book",
  "world": {"gravity": [0, 0, 0], "dt": 0.004166666666666667, "duration": 1},
  "render": {"fps": 30, "camera": {"position": [0.8, -1.2, 1.3], "target": [0, 0, 1]}},
  "bodies": [{"name": "ground", "shape": {"type": "plane"}},
             {"name": "book", "shape": {"type": "box", "size": [0.22, 0.05, 0.30]},
              "mass": 0.8, "position": [0, 0, 1], "angular_velocity": [0.5, 6, 0.5],
              "angular_velocity_frame": "body", "color": "#c0392b"}]})";

const char* const kSuite = R"({"format_version": 1, "title": "presentation", "goldens": "goldens",
  "image_defaults": {"width": 160, "height": 90,
                     "compare": {"max_different": 40, "perceptual_threshold": 0.05, "tolerance": 2}},
  "scenes": [{"scene": "spin.json", "images": [{"frames": [0, 15, 29]}],
              "states": [{"bodies": ["book"], "every": 5,
                          "quantities": {"position": 1e-6, "angular_velocity": 1e-6}}]}]})";

// Adds `delta` to the first `count` pixels' red channel (clamped).
void nudge(const std::filesystem::path& png, int delta, int count) {
    render::Image im = render::read_png(png);
    for (int p = 0; p < count; ++p) {
        const int at = 3 * (p * 37 % (im.width * im.height));
        im.rgb[std::size_t(at)] = std::uint8_t(std::clamp(im.rgb[std::size_t(at)] + delta, 0, 255));
    }
    render::write_png(png, im);
}

TEST(RegressionReport, ReadsRightStateFailuresFirstPassesAsPassesPlotsThatFit) {
    const auto dir = scratch_dir();
    write_text(dir / "spin.json", kScene);
    write_text(dir / "suite.json", kSuite);
    ASSERT_EQ(run_tumble(dir, "test suite.json --update").exit_code, 0);
    const auto goldens = dir / "goldens";
    ASSERT_TRUE(std::filesystem::exists(goldens / "spin_states.csv"));
    // A state golden off by 1e-3 rad/s in its last rows: the state check fails.
    std::string states = read_text(goldens / "spin_states.csv");
    const std::size_t comma = states.rfind(',');
    states = states.substr(0, comma + 1) +
             std::to_string(std::stod(states.substr(comma + 1)) + 1e-3) + "\n";
    write_text(goldens / "spin_states.csv", states);
    nudge(goldens / "spin_0015.png", 120, 400); // fails
    nudge(goldens / "spin_0029.png", 30, 10);   // passes: 10 pixels off, 40 allowed
    // The scene edited since: its title.
    std::string scene = kScene;
    scene.replace(scene.find("a spinning book"), 15, "a book, spinning");
    write_text(dir / "spin.json", scene);

    const CliResult r = run_tumble(dir, "test suite.json --report rep");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const std::string html = read_text(dir / "rep/index.html");
    // Failed state checks before failed image checks.
    const std::size_t state = html.find("data-check=\"spin_states\" data-status=\"failed\"");
    const std::size_t image = html.find("data-check=\"spin_0015\" data-status=\"failed\"");
    ASSERT_NE(state, std::string::npos);
    ASSERT_NE(image, std::string::npos);
    EXPECT_LT(state, image);
    // The pass is worded as one.
    const std::size_t pass = html.find("data-check=\"spin_0029\"");
    ASSERT_NE(pass, std::string::npos);
    const std::string pass_summary = html.substr(html.find("class=\"summary\"", pass), 300);
    EXPECT_TRUE(pass_summary.find("matches, not bit-identical") != std::string::npos ||
                pass_summary.find("identical within the tolerance") != std::string::npos)
        << pass_summary;
    EXPECT_EQ(pass_summary.find("pixels differ (allowed"), std::string::npos) << pass_summary;
    // The scene changed since its goldens: said for the image checks and the state check.
    const std::regex changed("the scene has changed since this golden was made");
    EXPECT_EQ(std::distance(std::sregex_iterator(html.begin(), html.end(), changed),
                            std::sregex_iterator()),
              4);

    // The plots: titles inside the plot's width (11 px sans-serif: under 6.5 px a character).
    const std::regex svg_re(R"re(<svg[^>]*width="([0-9.]+)"[\s\S]*?</svg>)re");
    int plots = 0;
    for (std::sregex_iterator it(html.begin(), html.end(), svg_re), end; it != end; ++it, ++plots) {
        const std::string svg = (*it)[0];
        const double width = std::stod((*it)[1]);
        const std::regex text_re(
            R"re(<text x="([0-9.]+)"[^>]*text-anchor="start">([^<]*)</text>)re");
        for (std::sregex_iterator t(svg.begin(), svg.end(), text_re); t != end; ++t)
            EXPECT_LE(std::stod((*t)[1]) + 6.5 * double((*t)[2].length()), width) << (*t)[2];
        // The value axis' ticks: the labels right-aligned left of the first panel, evenly apart
        // by a step of 1, 2 or 5 x 10^k.
        const std::regex tick_re(
            R"re(<text x="[0-9.]+" y="[0-9.]+" text-anchor="end">([-+0-9.e]+)</text>)re");
        std::vector<double> ticks;
        for (std::sregex_iterator t(svg.begin(), svg.end(), tick_re); t != end; ++t)
            if ((*t)[1].str().find("e") == std::string::npos) ticks.push_back(std::stod((*t)[1]));
        ASSERT_GE(ticks.size(), 3u) << svg.substr(0, 400);
        const double step = std::abs(ticks[1] - ticks[0]);
        const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
        EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 ||
                    std::abs(mantissa - 5) < 1e-6)
            << step;
        for (std::size_t k = 1; k < ticks.size(); ++k)
            EXPECT_NEAR(std::abs(ticks[k] - ticks[k - 1]), step, 1e-9 * step);
        // The tolerance band in the value panel: at least 3 px thick wherever it is drawn.
        std::smatch band;
        ASSERT_TRUE(
            std::regex_search(svg, band, std::regex(R"re(class="band" points="([^"]+)")re")));
        std::vector<double> ys;
        std::istringstream pts(band[1]);
        for (std::string xy; pts >> xy;) ys.push_back(std::stod(xy.substr(xy.find(',') + 1)));
        const std::size_t n = ys.size() / 2;
        for (std::size_t k = 0; k < n; ++k) EXPECT_GE(ys[2 * n - 1 - k] - ys[k], 2.99) << k;
    }
    EXPECT_GE(plots, 1);
}

} // namespace
} // namespace tumble::test
