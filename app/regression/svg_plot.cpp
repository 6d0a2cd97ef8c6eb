#include "app/regression/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::app {
namespace {

constexpr double kWidth = 520, kPanel = 110, kLeft = 70, kRight = 12, kTop = 22, kGap = 26;

struct Axis { // maps [lo, hi] onto [top + height, top]
    double lo, hi, top, height;
    double y(double v) const { return top + height - (v - lo) / (hi - lo) * height; }
};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string coord(double x, double y) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.1f,%.1f ", x, y);
    return buf;
}

// [lo, hi] with a margin; a range starting at 0 (a deviation) keeps 0 as its floor.
Axis axis_for(double lo, double hi, double top) {
    if (!(hi > lo)) {
        const double pad = std::max(std::abs(lo) * 1e-3, 1e-12);
        hi += pad;
        if (lo != 0) lo -= pad;
    }
    const double pad = 0.06 * (hi - lo);
    return {lo == 0 ? 0 : lo - pad, hi + pad, top, kPanel};
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
            if (std::isfinite(v[k])) pts += coord(x(s_.t[k]), a.y(std::clamp(v[k], a.lo, a.hi)));
        return "<polyline class=\"" + std::string(cls) + "\" points=\"" + pts + "\"/>\n";
    }
    std::string band(const std::vector<double>& lower, const std::vector<double>& upper,
                     const Axis& a) const {
        std::string pts;
        for (std::size_t k = 0; k < upper.size(); ++k)
            pts += coord(x(s_.t[k]), a.y(std::clamp(upper[k], a.lo, a.hi)));
        for (std::size_t k = lower.size(); k-- > 0;)
            pts += coord(x(s_.t[k]), a.y(std::clamp(lower[k], a.lo, a.hi)));
        return "<polygon class=\"band\" points=\"" + pts + "\"/>\n";
    }
    std::string frame(const Axis& a, const std::string& label) const {
        std::string out = "<rect class=\"frame\" x=\"" + num(kLeft) + "\" y=\"" + num(a.top) +
                          "\" width=\"" + num(kWidth - kLeft - kRight) + "\" height=\"" +
                          num(a.height) + "\"/>\n";
        out += "<text x=\"4\" y=\"" + num(a.top + 10) + "\">" + num(a.hi) + "</text>\n";
        out += "<text x=\"4\" y=\"" + num(a.top + a.height) + "\">" + num(a.lo) + "</text>\n";
        out += "<text x=\"" + num(kLeft + 4) + "\" y=\"" + num(a.top - 5) + "\">" + label +
               "</text>\n";
        return out;
    }
    std::string marker(const Axis& a, double v) const {
        if (s_.first_out < 0) return "";
        const double t = s_.t[std::size_t(s_.first_out)];
        return "<circle class=\"out\" cx=\"" + num(x(t)) + "\" cy=\"" +
               num(a.y(std::clamp(v, a.lo, a.hi))) + "\" r=\"4\"/>\n";
    }
    std::string time_axis(double y) const {
        return "<text x=\"" + num(kLeft) + "\" y=\"" + num(y) + "\">t = " + num(t0_) +
               " s</text><text x=\"" + num(kWidth - kRight - 80) + "\" y=\"" + num(y) +
               "\">t = " + num(t1_) + " s</text>\n";
    }

  private:
    const Series& s_;
    double t0_, t1_;
};

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
    std::vector<double> upper(n), lower(n), tol(n, s.tolerance), zero(n, 0.0);
    for (std::size_t k = 0; k < n; ++k)
        upper[k] = s.golden[k] + s.tolerance, lower[k] = s.golden[k] - s.tolerance;
    const auto [vlo, vhi] = range({&s.actual, &s.golden, &upper, &lower});
    const Axis value = axis_for(vlo, vhi, kTop);
    const auto [dlo, dhi] = range({&s.deviation, &tol, &zero});
    const Axis dev = axis_for(dlo, dhi, kTop + kPanel + kGap);
    const std::string unit = quantity_unit(s.quantity);
    const double height = dev.top + kPanel + 18;
    std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" viewBox=\"0 0 " +
                      num(kWidth) + " " + num(height) + "\" width=\"" + num(kWidth) +
                      "\" height=\"" + num(height) + "\" role=\"img\">\n";
    out += plot.frame(value, std::string(quantity_name(s.quantity)) + " " + s.component + " (" +
                                 unit + "): golden (dashed) +- tolerance (band), this run (blue)");
    out += plot.band(lower, upper, value);
    out += plot.polyline(s.golden, value, "golden");
    out += plot.polyline(s.actual, value, "actual");
    if (s.first_out >= 0) out += plot.marker(value, s.actual[std::size_t(s.first_out)]);
    out += plot.frame(dev, "|this run - golden| (" + unit + ") against the tolerance " +
                               num(s.tolerance) + " (band)");
    out += plot.band(zero, tol, dev);
    out += plot.polyline(s.deviation, dev, "actual");
    if (s.first_out >= 0) out += plot.marker(dev, s.deviation[std::size_t(s.first_out)]);
    out += plot.time_axis(height - 4);
    return out + "</svg>\n";
}

} // namespace tumble::app
