// Issue 30, item 2: a strip chart's labels sit where a reader looks for them. The time axis is
// labelled at its two ends (the run's end time at the right end, not mid-axis), the y range's
// ends are labelled in their own rows (not on the time labels' row), the y labels are whole
// multiples of a step of 1, 2 or 5 x 10^k, a 0 line crosses the plot when the range spans 0, and
// a vector's chart names its components in the colours of their curves. Read from the frame's
// canvas as `render --chart` draws it.
#include "app/cli/render_setup.h"
#include "app/run/frame_source.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace tumble::app {
namespace {

bool is_number(const std::string& s, double& v) {
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return !s.empty() && *end == '\0';
}

TEST(StripChart, AxesAreLabelledAtTheirEndsWithAZeroLineAndALegend) {
    RenderCommand cmd;
    cmd.common.scene = "lessons/intermediate_axis"; // w_body swings between -6 and 6 rad/s
    cmd.common.quiet = true;
    cmd.chart = std::vector<std::string>{"w_body"};
    cmd.chart_body = "book";
    cmd.width = 640, cmd.height = 360;
    Scene scene = load_for_command(cmd.common);
    apply_render_overrides(cmd, scene);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    Simulation sim = make_simulation(scene, tl.h);
    FrameSource frames(scene, tl, sim, 600, 600);
    render::SceneView view;
    ASSERT_TRUE(frames.next(view));
    const render::Canvas& c = view.canvas;
    ASSERT_EQ(c.rects.size(), 1u);
    const glm::vec2 lo = c.rects[0].min, hi = c.rects[0].max;
    const float width = hi.x - lo.x;
    // The time labels: "0 s" at the left end, "12 s" (the run's end) at the right end.
    const render::Canvas::Label *start = nullptr, *end = nullptr;
    std::vector<const render::Canvas::Label*> values;
    for (const auto& l : c.labels) {
        double v = 0;
        if (l.text == "0 s") start = &l;
        if (l.text == "12 s") end = &l;
        if (is_number(l.text, v)) values.push_back(&l);
    }
    ASSERT_TRUE(start && end);
    EXPECT_EQ(start->align, -1);
    EXPECT_LT(start->at.x - lo.x, 0.1f * width);
    EXPECT_EQ(end->align, 1); // its right end at the axis' right end
    EXPECT_GT(end->at.x - lo.x, 0.9f * width);
    // The y range's ends: two numbers (a third, "0", on the zero line), in rows of their own.
    ASSERT_GE(values.size(), 2u);
    const auto [top, bottom] = std::minmax_element(
        values.begin(), values.end(), [](auto* a, auto* b) { return a->at.y < b->at.y; });
    double y_hi = 0, y_lo = 0;
    ASSERT_TRUE(is_number((*top)->text, y_hi) && is_number((*bottom)->text, y_lo));
    EXPECT_GT(y_hi, 6.0);
    EXPECT_LT(y_lo, -6.0);
    for (const auto* l : values) EXPECT_GT(std::abs(l->at.y - end->at.y), 2.0f) << l->text;
    // Whole multiples of one nice step, the box at most one step beyond the data.
    bool nice = false;
    for (double step : {1.0, 2.0, 5.0, 10.0})
        nice |= std::fmod(y_hi, step) == 0 && std::fmod(y_lo, step) == 0 && y_hi - 6.0 <= step &&
                -6.0 - y_lo <= step;
    EXPECT_TRUE(nice) << y_lo << " .. " << y_hi;
    // The 0 line: a horizontal stroke across the plot, between the two ends' rows.
    bool zero_line = false;
    for (const auto& s : c.strips) {
        if (s.count != 2) continue;
        const glm::vec2 a = c.points[s.first], b = c.points[s.first + 1];
        const float y0 = (*top)->at.y, y1 = (*bottom)->at.y;
        const float expected = y0 + float(y_hi / (y_hi - y_lo)) * (y1 - y0);
        zero_line |= a.y == b.y && std::abs(b.x - a.x) > 0.8f * width && a.y > y0 && a.y < y1 &&
                     std::abs(a.y - expected) < 0.2f * (y1 - y0);
    }
    EXPECT_TRUE(zero_line);
    // A legend: "x", "y", "z", each in the colour of one of the three curves.
    std::vector<glm::vec4> curves;
    for (const auto& s : c.strips)
        if (s.count > 20) curves.push_back(s.rgba);
    ASSERT_EQ(curves.size(), 3u);
    for (const char* name : {"x", "y", "z"}) {
        const auto l = std::find_if(c.labels.begin(), c.labels.end(),
                                    [&](const auto& label) { return label.text == name; });
        ASSERT_NE(l, c.labels.end()) << name;
        EXPECT_EQ(l->rgba, curves[std::size_t(name[0] - 'x')]) << name;
    }
}

} // namespace
} // namespace tumble::app
