// The overlay's numbers (issue 14, item 6): the digits that mean something, in fields of fixed
// width. Before, every quantity was printed in 10-digit scientific notation ("E
// +4.108047573e+00 J"), which filled a compare tile's width and said nothing more.
#include "app/view/overlay_text.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tumble::app {
namespace {

OverlayInfo info(double kinetic, double potential, const physics::Vec3& p) {
    OverlayInfo o;
    o.t = 1.0;
    o.step = 240;
    o.integrator = "rk4";
    o.h = 1.0 / 240.0;
    o.initial.kinetic_linear = 4.0;
    o.now.kinetic_linear = kinetic;
    o.now.potential = potential;
    o.now.linear_momentum = p;
    o.now.angular_momentum = physics::Vec3(0.0669, -0.0662, 1.697e-4);
    return o;
}

TEST(OverlayText, EnergyHasSixSignificantDigitsAndMomentaThree) {
    std::vector<std::string> lines;
    overlay_lines(info(4.108047573, 0.0, physics::Vec3(0.0, 0.0, -0.0331)), lines);
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_NE(lines[2].find("+4.10805 J"), std::string::npos) << lines[2];
    EXPECT_NE(lines[2].find("dE/|E0| +2.7e-02"), std::string::npos) << lines[2];
    EXPECT_NE(lines[3].find("-0.0331 kg m/s"), std::string::npos) << lines[3];
    EXPECT_NE(lines[4].find("+0.000170 kg m^2/s"), std::string::npos) << lines[4];
    for (const std::string& line : lines) EXPECT_EQ(line.find("e+00"), std::string::npos) << line;
}

// The text must not jiggle from frame to frame: lines keep their length as the values change
// within their magnitude, and the panel (the longest line) stays narrow.
TEST(OverlayText, FieldsKeepTheirWidth) {
    std::vector<std::string> a, b;
    overlay_lines(info(4.108047573, 0.0, physics::Vec3(0.0, 0.0, -0.0331)), a);
    overlay_lines(info(4.2, -0.1, physics::Vec3(0.5, -1.25e-5, 0.0)), b);
    for (std::size_t i = 2; i < a.size(); ++i) EXPECT_EQ(a[i].size(), b[i].size()) << a[i] << b[i];
    std::size_t widest = 0;
    for (const std::string& line : a) widest = std::max(widest, line.size());
    EXPECT_LE(widest, 46u); // was 52 characters
}

// The error estimate's line (--error-estimate): the largest estimate of the bodies it holds for,
// how many it no longer holds for, and no wider than the rest of the panel.
TEST(OverlayText, ErrorEstimateLine) {
    std::vector<std::string> lines;
    OverlayInfo o = info(4.108047573, 0.0, physics::Vec3(0.0, 0.0, -0.0331));
    overlay_lines(o, lines);
    ASSERT_EQ(lines.size(), 5u); // off: no line
    o.estimate = {true, 3.04e-6, 2e-9, 1, 0};
    overlay_lines(o, lines);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[5], "err <= 3.0e-06 rad, 2.0e-09 m (step doubling)");
    o.estimate = {true, 3.04e-6, 2e-9, 1, 3};
    overlay_lines(o, lines);
    EXPECT_EQ(lines[5], "err <= 3.0e-06 rad, 2.0e-09 m; n/a for 3");
    o.estimate = {true, 0.0, 0.0, 0, 3};
    overlay_lines(o, lines);
    EXPECT_EQ(lines[5], "err n/a: contact or sleep (step doubling)");
    o.estimate = {true, 3.1, 2e-9, 1, 0}; // an estimate of pi rad or more: still the same width
    overlay_lines(o, lines);
    for (const std::string& line : lines) EXPECT_LE(line.size(), 46u) << line;
}

} // namespace
} // namespace tumble::app
