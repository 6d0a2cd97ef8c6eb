#include "app/view/strip_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::app {

ChartHistory::ChartHistory(const ChartSettings& settings, const physics::Model& model,
                           const physics::State& initial)
    : settings_(settings), e0_(chart_energy(model, initial, settings.body)) {
    record(model, initial);
}

void ChartHistory::record(const physics::Model& model, const physics::State& state) {
    times_.push_back(state.time(model));
    for (ChartQuantity q : settings_.quantities) {
        const auto v = measure(q, model, state, settings_.body, e0_);
        values_.insert(values_.end(), v.begin(), v.end());
    }
}

std::pair<double, double> nice_range(double lo, double hi) {
    double span = hi - lo;
    if (!(span > 0.0)) span = std::max(std::abs(hi), 1e-12);
    // A step near a fifth of the span: 1, 2 or 5 times a power of ten.
    const double raw = span / 5.0;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw <= decade       ? decade
                        : raw <= 2 * decade ? 2 * decade
                        : raw <= 5 * decade ? 5 * decade
                                            : 10 * decade;
    double a = std::floor(lo / step) * step, b = std::ceil(hi / step) * step;
    if (a == lo) a -= step; // room above and below the line
    if (b == hi) b += step;
    return {a, b};
}

void ChartScale::include(const ChartHistory& h, std::size_t from) {
    for (std::size_t p = 0; p < h.panels(); ++p) {
        const int n = chart_quantity_info(h.settings().quantities[p]).components;
        double lo = ranges_[p].first, hi = ranges_[p].second;
        bool seen = seen_[p], grew = false;
        for (std::size_t k = from; k < h.samples(); ++k) {
            for (int c = 0; c < n; ++c) {
                const double v = h.value(p, c, k);
                if (!std::isfinite(v)) continue;
                if (!seen) lo = hi = v, seen = grew = true;
                if (v < lo || v > hi) lo = std::min(lo, v), hi = std::max(hi, v), grew = true;
            }
        }
        seen_[p] = seen;
        if (grew) ranges_[p] = nice_range(lo, hi);
    }
}

namespace {

constexpr glm::vec4 kPanel{0.05f, 0.06f, 0.08f, 0.62f};
constexpr glm::vec4 kAxis{1.0f, 1.0f, 1.0f, 0.35f};
constexpr glm::vec4 kText{1.0f, 1.0f, 1.0f, 0.92f};
constexpr glm::vec4 kScalar{1.0f, 0.78f, 0.25f, 1.0f};      // amber
constexpr glm::vec4 kXyz[3] = {{1.0f, 0.38f, 0.32f, 1.0f},  // x red
                               {0.45f, 0.9f, 0.4f, 1.0f},   // y green
                               {0.45f, 0.65f, 1.0f, 1.0f}}; // z blue

std::string number(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.3g", std::abs(v) < 1e-300 ? 0.0 : v);
    return s;
}

std::string title(const ChartHistory& h, ChartQuantity q) {
    const ChartQuantityInfo& i = chart_quantity_info(q);
    std::string t =
        (h.settings().body < 0 ? std::string("scene") : h.settings().body_name) + ": " + i.name;
    if (i.components == 3) t += " (x y z)";
    if (*i.unit) t += std::string(", ") + i.unit;
    return t;
}

// One panel: the box, its labels, the zero line and the series.
void panel(const ChartHistory& h, std::size_t p, std::pair<double, double> y, double t0, double t1,
           glm::vec2 lo, glm::vec2 hi, float font, render::Canvas& c) {
    c.rects.push_back({lo, hi, kPanel});
    const ChartQuantity q = h.settings().quantities[p];
    const glm::vec2 plot_lo(lo.x + 0.5f * font, lo.y + 1.6f * font);
    const glm::vec2 plot_hi(hi.x - 0.5f * font, hi.y - 1.4f * font);
    c.labels.push_back({{lo.x + 0.5f * font, lo.y + 1.1f * font}, title(h, q), kText, -1});
    c.labels.push_back({{hi.x - 0.5f * font, lo.y + 1.1f * font}, number(y.second), kText, 1});
    c.labels.push_back({{hi.x - 0.5f * font, hi.y - 0.35f * font}, number(y.first), kText, 1});
    c.labels.push_back({{lo.x + 0.5f * font, hi.y - 0.35f * font}, number(t0) + " s", kText, -1});
    c.labels.push_back({{0.5f * (lo.x + hi.x), hi.y - 0.35f * font}, number(t1) + " s", kText, 0});
    const auto to_px = [&](double t, double v) {
        const double u = (t - t0) / (t1 - t0), w = (v - y.first) / (y.second - y.first);
        return glm::vec2(plot_lo.x + float(u) * (plot_hi.x - plot_lo.x),
                         plot_hi.y - float(w) * (plot_hi.y - plot_lo.y));
    };
    auto line = [&](glm::vec2 a, glm::vec2 b, glm::vec4 rgba, float width) {
        c.strips.push_back({std::uint32_t(c.points.size()), 2, rgba, width});
        c.points.push_back(a);
        c.points.push_back(b);
    };
    line({plot_lo.x, plot_hi.y}, {plot_hi.x, plot_hi.y}, kAxis, 1.0f);
    if (y.first < 0.0 && y.second > 0.0) line(to_px(t0, 0.0), to_px(t1, 0.0), kAxis, 1.0f);
    // The samples in [t0, t1], at most about one per pixel column.
    std::size_t first = 0;
    while (first < h.samples() && h.time(first) < t0) ++first;
    const std::size_t n = h.samples() - first;
    const std::size_t stride =
        std::max<std::size_t>(1, n / std::max(1, int(plot_hi.x - plot_lo.x)));
    const int components = chart_quantity_info(q).components;
    for (int comp = 0; comp < components; ++comp) {
        render::Canvas::Strip s{std::uint32_t(c.points.size()), 0,
                                components == 1 ? kScalar : kXyz[comp],
                                std::max(1.5f, 0.12f * font)};
        for (std::size_t k = first; k < h.samples(); k += stride) {
            const double v = h.value(p, comp, k);
            if (!std::isfinite(v)) continue;
            c.points.push_back(to_px(h.time(k), std::clamp(v, y.first, y.second)));
            ++s.count;
        }
        if (s.count >= 2)
            c.strips.push_back(s);
        else
            c.points.resize(s.first);
    }
}

} // namespace

void draw_charts(const ChartHistory& h, const ChartScale& scale, double now, double duration,
                 int width, int height, render::Canvas& canvas) {
    const std::size_t n = h.panels();
    if (n == 0) return;
    const float font = std::max(9.0f, std::min(float(height) / 40.0f, float(width) / 32.0f));
    const float margin = std::round(0.8f * font);
    const float w = std::round(std::max(0.42f * float(width), 22.0f * font));
    const float ph = std::round(std::max(0.16f * float(height), 5.5f * font));
    const double window = h.settings().window;
    double t0 = 0.0, t1 = duration > 0.0 ? duration : std::max(now, 1e-9);
    if (window > 0.0) t0 = std::max(0.0, now - window), t1 = std::max(t0 + window, now);
    for (std::size_t p = 0; p < n; ++p) {
        const float bottom = float(height) - margin - float(n - 1 - p) * (ph + 0.5f * margin);
        panel(h, p, scale.range(p), t0, t1, {float(width) - margin - w, bottom - ph},
              {float(width) - margin, bottom}, font, canvas);
    }
}

} // namespace tumble::app
