#include "app/view/strip_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::app {

ChartHistory::ChartHistory(const ChartSettings& settings, const physics::Model& model,
                           const physics::State& initial)
    : settings_(settings), e0_(energy_of(model, initial, settings.body)) {
    record(model, initial);
}

void ChartHistory::record(const physics::Model& model, const physics::State& state) {
    times_.push_back(state.time(model));
    for (Quantity q : settings_.quantities) {
        const auto v = quantity_value(q, model, state, settings_.body, e0_);
        values_.insert(values_.end(), v.begin(), v.end());
    }
}

void ChartScale::include(const ChartHistory& h, std::size_t from) {
    for (std::size_t p = 0; p < h.panels(); ++p) {
        const int n = quantity_info(h.settings().quantities[p]).components;
        Panel& s = panels_[p];
        bool outside = false;
        for (std::size_t k = from; k < h.samples(); ++k) {
            for (int c = 0; c < n; ++c) {
                const double v = h.value(p, c, k);
                if (!std::isfinite(v)) continue;
                if (!s.seen) s.lo = s.hi = v, s.seen = outside = true;
                s.lo = std::min(s.lo, v), s.hi = std::max(s.hi, v);
                outside |= v < s.box.lo || v > s.box.hi;
            }
        }
        if (!s.seen) continue;
        // Flat: varying by less than a millionth of its size (rounding, a conserved quantity).
        const bool flat = s.hi - s.lo <= 1e-6 * std::max(std::abs(s.lo), std::abs(s.hi));
        if (outside || (s.flat && !flat)) {
            const double mid = 0.5 * (s.lo + s.hi);
            // Steps near a tenth of the span: less than a tenth of slack at each end.
            s.box = flat ? render::nice_range(mid, mid, 10) : render::nice_range(s.lo, s.hi, 10);
            s.flat = flat;
        }
    }
}

namespace {

constexpr glm::vec4 kPanel{0.05f, 0.06f, 0.08f, 0.62f};
constexpr glm::vec4 kAxis{1.0f, 1.0f, 1.0f, 0.45f};
constexpr glm::vec4 kZero{1.0f, 1.0f, 1.0f, 0.6f};
constexpr glm::vec4 kText{1.0f, 1.0f, 1.0f, 0.92f};
constexpr glm::vec4 kDim{1.0f, 1.0f, 1.0f, 0.7f};
constexpr glm::vec4 kScalar{1.0f, 0.78f, 0.25f, 1.0f};      // amber
constexpr glm::vec4 kXyz[3] = {{1.0f, 0.38f, 0.32f, 1.0f},  // x red, as the body's x axis
                               {0.45f, 0.9f, 0.4f, 1.0f},   // y green
                               {0.45f, 0.65f, 1.0f, 1.0f}}; // z blue

std::string seconds(double t) {
    char s[32];
    std::snprintf(s, sizeof s, "%.3g s", std::abs(t) < 1e-9 ? 0.0 : t);
    return s;
}

// The longest of "book: w_body, rad/s", "w_body, rad/s", "w_body" that fits `columns`.
std::string title(const ChartHistory& h, Quantity q, std::size_t columns) {
    const QuantityInfo& i = quantity_info(q);
    const std::string name(i.name);
    const std::string unit = i.unit == "1" ? "" : ", " + std::string(i.unit); // dimensionless
    const std::string subject = h.settings().body < 0 ? "scene" : h.settings().body_name;
    for (const std::string& t : {subject + ": " + name + unit, name + unit})
        if (t.size() <= columns) return t;
    return name;
}

struct Frame {                  // one panel's parts, pixels
    glm::vec2 lo, hi;           // the panel
    glm::vec2 plot_lo, plot_hi; // the plot inside it
    float title_baseline, time_baseline;
};

Frame frame_of(const ScreenBox& box, const render::OverlayFont& f) {
    Frame r;
    r.lo = box.min, r.hi = box.max;
    const float pad = f.pad(), line = f.line_height;
    r.title_baseline = box.min.y + pad + f.ascent;
    r.time_baseline = box.max.y - pad - (line - f.ascent);
    r.plot_lo = {box.min.x + pad, box.min.y + pad + line + 0.35f * pad};
    r.plot_hi = {box.max.x - pad, box.max.y - pad - line - 0.35f * pad};
    return r;
}

void line(render::Canvas& c, glm::vec2 a, glm::vec2 b, glm::vec4 rgba, float width) {
    c.strips.push_back({std::uint32_t(c.points.size()), 2, rgba, width});
    c.points.push_back(a);
    c.points.push_back(b);
}

// The title on the left of the top row and, for a vector, "-x -y -z" in its colours on the right.
void heading(const ChartHistory& h, Quantity q, const Frame& fr, const render::OverlayFont& f,
             render::Canvas& c) {
    const int n = quantity_info(q).components;
    const float item = 2.6f * f.advance; // a stroke, a gap and the letter
    const float legend = n == 3 ? 3.0f * item + 2.0f * f.advance : 0.0f;
    const auto columns =
        std::size_t(std::max(0.0f, (fr.hi.x - fr.lo.x - 2 * f.pad() - legend) / f.advance));
    c.labels.push_back({{fr.plot_lo.x, fr.title_baseline}, title(h, q, columns), kText, -1});
    if (n != 3) return;
    const float mid = fr.title_baseline - 0.33f * f.pixel_height;
    float x = fr.plot_hi.x - legend + 2.0f * f.advance;
    for (int k = 0; k < 3; ++k, x += item) {
        line(c, {x, mid}, {x + 1.3f * f.advance, mid}, kXyz[k],
             std::max(2.0f, 0.2f * f.pixel_height));
        c.labels.push_back({{x + 1.6f * f.advance, fr.title_baseline},
                            std::string(1, char('x' + k)),
                            kXyz[k],
                            -1});
    }
}

// The axes: time along the bottom with its ends' times below it, the y range's ends inside the
// plot at its top and bottom left, and the 0 line with its label when the range spans 0.
void axes(const render::NiceRange& y, double t0, double t1, const Frame& fr,
          const render::OverlayFont& f, render::Canvas& c) {
    line(c, {fr.plot_lo.x, fr.plot_hi.y}, {fr.plot_hi.x, fr.plot_hi.y}, kAxis, 1.0f);
    line(c, {fr.plot_lo.x, fr.plot_lo.y}, {fr.plot_lo.x, fr.plot_hi.y}, kAxis, 1.0f);
    c.labels.push_back({{fr.plot_lo.x, fr.time_baseline}, seconds(t0), kDim, -1});
    c.labels.push_back({{fr.plot_hi.x, fr.time_baseline}, seconds(t1), kDim, 1});
    const float x = fr.plot_lo.x + 0.4f * f.advance;
    const float top = fr.plot_lo.y + f.ascent, bottom = fr.plot_hi.y - 0.25f * f.pad();
    c.labels.push_back({{x, top}, render::tick_label(y.hi, y.step), kDim, -1});
    c.labels.push_back({{x, bottom}, render::tick_label(y.lo, y.step), kDim, -1});
    if (!(y.lo < 0.0 && y.hi > 0.0)) return;
    const float zero = fr.plot_hi.y - float(-y.lo / (y.hi - y.lo)) * (fr.plot_hi.y - fr.plot_lo.y);
    line(c, {fr.plot_lo.x, zero}, {fr.plot_hi.x, zero}, kZero, 1.0f);
    const float baseline = zero + 0.5f * f.ascent;
    if (baseline - f.ascent > top + 1.0f && baseline < bottom - f.ascent - 1.0f)
        c.labels.push_back({{x, baseline}, "0", kDim, -1});
}

// One panel: the box, its labels, the axes and the series.
void panel(const ChartHistory& h, std::size_t p, const render::NiceRange& y, double t0, double t1,
           const Frame& fr, const render::OverlayFont& f, render::Canvas& c) {
    c.rects.push_back({fr.lo, fr.hi, kPanel});
    const Quantity q = h.settings().quantities[p];
    heading(h, q, fr, f, c);
    axes(y, t0, t1, fr, f, c);
    const auto to_px = [&](double t, double v) {
        const double u = (t - t0) / (t1 - t0), w = (v - y.lo) / (y.hi - y.lo);
        return glm::vec2(fr.plot_lo.x + float(u) * (fr.plot_hi.x - fr.plot_lo.x),
                         fr.plot_hi.y - float(w) * (fr.plot_hi.y - fr.plot_lo.y));
    };
    // The samples in [t0, t1], at most about one per pixel column.
    std::size_t first = 0;
    while (first < h.samples() && h.time(first) < t0) ++first;
    const std::size_t n = h.samples() - first;
    const std::size_t stride =
        std::max<std::size_t>(1, n / std::max(1, int(fr.plot_hi.x - fr.plot_lo.x)));
    const int components = quantity_info(q).components;
    for (int comp = 0; comp < components; ++comp) {
        render::Canvas::Strip s{std::uint32_t(c.points.size()), 0,
                                components == 1 ? kScalar : kXyz[comp],
                                std::max(1.5f, 0.12f * f.pixel_height)};
        for (std::size_t k = first; k < h.samples(); k += stride) {
            const double v = h.value(p, comp, k);
            if (!std::isfinite(v)) continue;
            c.points.push_back(to_px(h.time(k), std::clamp(v, y.lo, y.hi)));
            ++s.count;
        }
        if (s.count >= 2)
            c.strips.push_back(s);
        else
            c.points.resize(s.first);
    }
}

} // namespace

glm::vec2 chart_panel_size(const render::OverlayFont& font, int width, int height) {
    const float m = font.margin();
    // Wide enough for a short title and its legend; tall enough for a title, a plot three lines
    // high and the times.
    const float w =
        std::min(std::max(0.36f * float(width), 24.0f * font.advance), float(width) - 2.0f * m);
    const float h = std::max(0.16f * float(height), 2.0f * font.pad() + 5.0f * font.line_height);
    return {std::round(w), std::round(h)};
}

void draw_charts(const ChartHistory& h, const ChartScale& scale, double now, double duration,
                 const render::OverlayFont& font, const std::vector<ScreenBox>& boxes,
                 render::Canvas& canvas) {
    const double window = h.settings().window;
    double t0 = 0.0, t1 = duration > 0.0 ? duration : std::max(now, 1e-9);
    if (window > 0.0) t0 = std::max(0.0, now - window), t1 = std::max(t0 + window, now);
    for (std::size_t p = 0; p < h.panels() && p < boxes.size(); ++p)
        panel(h, p, scale.range(p), t0, t1, frame_of(boxes[p], font), font, canvas);
}

} // namespace tumble::app
