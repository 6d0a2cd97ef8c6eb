#include "app/regression/svg_plot.h"

#include "render/nice_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::app {
namespace {

// Pixels: the plot's width, each panel's height, the room left of the panels for tick labels
// (eight characters of the report's 11 px font), the rows of titles and legend above each panel.
constexpr double kWidth = 560, kPanel = 110, kLeft = 64, kRight = 12, kTitle = 16, kGap = 10;
constexpr double kMinBand = 3; // the tolerance band is drawn at least this thick

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

std::string coord(double x, double y) {
    return num(x) + "," + num(y) + " ";
}

std::string text(double x, double y, const std::string& s, const char* anchor = "start") {
    return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + anchor + "\">" + s +
           "</text>\n";
}

// A vertical axis: linear over a nice range, or logarithmic over whole decades.
struct Axis {
    double lo, hi, top;
    bool log = false;
    double step = 1; // between labelled ticks: a nice step, or decades
    double y(double v) const {
        const double u = log ? (v > 0 ? std::log10(v) : lo) : v;
        return top + kPanel - (std::clamp(u, lo, hi) - lo) / (hi - lo) * kPanel;
    }
    std::string label(double u) const {
        if (!log) return render::tick_label(u, step);
        char buf[16];
        std::snprintf(buf, sizeof buf, "1e%+03d", int(std::lround(u)));
        return buf;
    }
};

Axis linear_axis(double lo, double hi, double top) {
    const render::NiceRange r = render::nice_range(lo, hi);
    return {r.lo, r.hi, top, false, r.step};
}

// Decades from below the smaller of the tolerance and the smallest deviation (a zero deviation
// sits on the floor) to above the largest, at most twelve of them.
Axis log_axis(const std::vector<double>& deviation, double tolerance, double top) {
    double smallest = tolerance > 0 ? tolerance : 1.0, largest = smallest;
    for (double d : deviation)
        if (std::isfinite(d) && d > 0)
            smallest = std::min(smallest, d), largest = std::max(largest, d);
    const double hi = std::ceil(std::log10(largest) + 1e-9);
    double lo = std::min(std::floor(std::log10(smallest)),
                         std::floor(std::log10(tolerance > 0 ? tolerance : 1.0)) - 2);
    lo = std::max(lo, hi - 12);
    if (hi - lo < 3) lo = hi - 3;
    return {lo, hi, top, true, std::ceil((hi - lo) / 6)};
}

class Plot {
  public:
    explicit Plot(const Series& s) : s_(s) {
        t0_ = s.t.front(), t1_ = s.t.back() > s.t.front() ? s.t.back() : s.t.front() + 1;
    }
    double x(double t) const { return kLeft + (t - t0_) / (t1_ - t0_) * (kWidth - kLeft - kRight); }

    std::string polyline(const std::vector<double>& v, const Axis& a, const char* cls) const {
        std::string pts;
        for (std::size_t k = 0; k < v.size(); ++k)
            if (std::isfinite(v[k])) pts += coord(x(s_.t[k]), a.y(v[k]));
        return "<polyline class=\"" + std::string(cls) + "\" points=\"" + pts + "\"/>\n";
    }
    // The band between lower and upper, at least kMinBand pixels thick about `middle`.
    std::string band(const std::vector<double>& lower, const std::vector<double>& upper,
                     const std::vector<double>& middle, const Axis& a) const {
        std::string top, bottom;
        for (std::size_t k = 0; k < upper.size(); ++k) {
            double yu = a.y(upper[k]), yl = a.y(lower[k]);
            if (yl - yu < kMinBand) {
                const double ym = a.y(middle[k]);
                yu = std::min(yu, ym - 0.5 * kMinBand), yl = std::max(yl, ym + 0.5 * kMinBand);
            }
            top += coord(x(s_.t[k]), yu);
            bottom = coord(x(s_.t[k]), yl) + bottom;
        }
        return "<polygon class=\"band\" points=\"" + top + bottom + "\"/>\n";
    }
    // The panel's frame, its grid and tick labels, and its title above it.
    std::string frame(const Axis& a, const std::string& title) const {
        std::string out = "<rect class=\"frame\" x=\"" + num(kLeft) + "\" y=\"" + num(a.top) +
                          "\" width=\"" + num(kWidth - kLeft - kRight) + "\" height=\"" +
                          num(kPanel) + "\"/>\n";
        const double first = std::ceil(a.lo / a.step - 1e-9) * a.step;
        for (double u = first; u <= a.hi + 1e-9 * a.step; u += a.step) {
            const double y = a.top + kPanel - (u - a.lo) / (a.hi - a.lo) * kPanel;
            out += "<line class=\"grid\" x1=\"" + num(kLeft) + "\" x2=\"" + num(kWidth - kRight) +
                   "\" y1=\"" + num(y) + "\" y2=\"" + num(y) + "\"/>\n";
            out += text(kLeft - 4, y + 4, a.label(u), "end");
        }
        return out + text(kLeft, a.top - 6, title);
    }
    std::string marker(const Axis& a, double v) const {
        if (s_.first_out < 0) return "";
        const double t = s_.t[std::size_t(s_.first_out)];
        return "<circle class=\"out\" cx=\"" + num(x(t)) + "\" cy=\"" + num(a.y(v)) +
               "\" r=\"4\"/>\n";
    }
    std::string time_axis(double y) const {
        return text(kLeft, y,
                    "t = " + render::tick_label(t0_, render::nice_step(t1_ - t0_)) + " s") +
               text(kWidth - kRight, y,
                    "t = " + render::tick_label(t1_, render::nice_step(t1_ - t0_)) + " s", "end");
    }

  private:
    const Series& s_;
    double t0_, t1_;
};

// What the lines and the band are, in one row: a dashed stroke, a blue stroke, a green swatch.
std::string legend(double y) {
    const double x = kLeft;
    return "<line class=\"golden\" x1=\"" + num(x) + "\" x2=\"" + num(x + 22) + "\" y1=\"" +
           num(y - 4) + "\" y2=\"" + num(y - 4) + "\"/>" + text(x + 26, y, "golden") +
           "<line class=\"actual\" x1=\"" + num(x + 80) + "\" x2=\"" + num(x + 102) + "\" y1=\"" +
           num(y - 4) + "\" y2=\"" + num(y - 4) + "\"/>" + text(x + 106, y, "this run") +
           "<rect class=\"band\" x=\"" + num(x + 168) + "\" y=\"" + num(y - 9) +
           "\" width=\"22\" height=\"10\"/>" +
           text(x + 194, y, "golden \u00b1 tolerance (at least 3 px thick)");
}

std::pair<double, double> range(std::initializer_list<const std::vector<double>*> all) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto* v : all)
        for (double x : *v)
            if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    if (!std::isfinite(lo)) lo = 0, hi = 1;
    return {lo, hi};
}

} // namespace

std::string svg_plot(const Series& s) {
    if (s.t.empty()) return "";
    const Plot plot(s);
    const std::size_t n = s.t.size();
    std::vector<double> upper(n), lower(n), zero(n, 0.0), tol(n, s.tolerance);
    for (std::size_t k = 0; k < n; ++k)
        upper[k] = s.golden[k] + s.tolerance, lower[k] = s.golden[k] - s.tolerance;
    const auto [vlo, vhi] = range({&s.actual, &s.golden, &upper, &lower});
    const Axis value = linear_axis(vlo, vhi, kTitle * 2 + kGap);
    const Axis dev = log_axis(s.deviation, s.tolerance, value.top + kPanel + kTitle + 2 * kGap);
    const std::string unit = quantity_unit(s.quantity);
    const double height = dev.top + kPanel + kTitle + 4;
    std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" viewBox=\"0 0 " +
                      num(kWidth) + " " + num(height) + "\" width=\"" + num(kWidth) +
                      "\" height=\"" + num(height) + "\" role=\"img\">\n";
    out += legend(kTitle);
    out +=
        plot.frame(value, std::string(quantity_name(s.quantity)) + " " + s.component + ", " + unit);
    out += plot.band(lower, upper, s.golden, value);
    out += plot.polyline(s.golden, value, "golden");
    out += plot.polyline(s.actual, value, "actual");
    if (s.first_out >= 0) out += plot.marker(value, s.actual[std::size_t(s.first_out)]);
    char tolerance[32];
    std::snprintf(tolerance, sizeof tolerance, "%.3g", s.tolerance);
    out += plot.frame(dev, "|this run - golden|, " + unit + ", log scale; tolerance " + tolerance +
                               " (band)");
    out += plot.band(zero, tol, tol, dev);
    out += plot.polyline(s.deviation, dev, "actual");
    if (s.first_out >= 0) out += plot.marker(dev, s.deviation[std::size_t(s.first_out)]);
    out += plot.time_axis(height - 4);
    return out + "</svg>\n";
}

} // namespace tumble::app
