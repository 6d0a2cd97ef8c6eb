#include "app/view/overlay_text.h"

#include <cmath>
#include <cstdio>

namespace tumble::app {
namespace {

template <class... Args>
void set_line(std::string& line, const char* format, Args... args) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, format, args...);
    line.assign(buffer);
}

// "err <= 3.0e-06 rad, 2.0e-09 m (step doubling)", or how many bodies it no longer holds for
// (contacts, sleep), within the panel's width.
void estimate_line(const OverlayEstimate& e, std::string& line) {
    if (e.holding == 0)
        set_line(line, "err n/a: contact or sleep (step doubling)");
    else if (e.not_holding == 0)
        set_line(line, "err <= %.1e rad, %.1e m (step doubling)", e.rotation, e.position);
    else
        set_line(line, "err <= %.1e rad, %.1e m; n/a for %d", e.rotation, e.position,
                 e.not_holding);
}

// E's drift: relative when the energy is not near zero, absolute otherwise.
struct Drift {
    bool relative;
    double value;
};
Drift drift(const OverlayInfo& o) {
    const double e0 = o.initial.energy(), e = o.now.energy();
    const bool relative = std::abs(e0) > 1e-12;
    return {relative, relative ? (e - e0) / std::abs(e0) : e - e0};
}

void compact_lines(const OverlayInfo& o, std::vector<std::string>& lines) {
    lines.resize(3 + (o.estimate.on ? 1 : 0));
    set_line(lines[0], "%s h %.3g ms", std::string(o.integrator).c_str(), o.h * 1e3);
    set_line(lines[1], "t %.3f s", o.t);
    const Drift d = drift(o);
    set_line(lines[2], d.relative ? "dE/|E0| %+.1e" : "dE %+.1e J", d.value);
    if (o.estimate.on && o.estimate.holding > 0)
        set_line(lines[3], "err <= %.1e rad", o.estimate.rotation);
    else if (o.estimate.on)
        set_line(lines[3], "err n/a");
}

} // namespace

void overlay_lines(const OverlayInfo& o, std::vector<std::string>& lines, bool compact) {
    if (compact) return compact_lines(o, lines);
    lines.resize((o.subject.empty() ? 5 : 6) + (o.estimate.on ? 1 : 0));
    const double e = o.now.energy();
    const auto [relative, change] = drift(o);
    set_line(lines[0], "t %.4f s   step %lld", o.t, static_cast<long long>(o.step));
    set_line(lines[1], "%s   h %.4g ms", std::string(o.integrator).c_str(), o.h * 1e3);
    // The digits that mean something, in fields of fixed width (the text must not jiggle): E to
    // six significant digits, its drift to two, momenta to three.
    if (relative)
        set_line(lines[2], "E %#+11.6g J  dE/|E0| %+.1e", e, change);
    else
        set_line(lines[2], "E %#+11.6g J  dE %+.1e J", e, change);
    const physics::Vec3& p = o.now.linear_momentum;
    const physics::Vec3& l = o.now.angular_momentum;
    set_line(lines[3], "p %#+10.3g %#+10.3g %#+10.3g kg m/s", p.x(), p.y(), p.z());
    set_line(lines[4], "L %#+10.3g %#+10.3g %#+10.3g kg m^2/s", l.x(), l.y(), l.z());
    if (!o.subject.empty())
        set_line(lines[5], "(E, p of body \"%s\"; L its spin about its centre)",
                 std::string(o.subject).c_str());
    if (o.estimate.on) estimate_line(o.estimate, lines.back());
}

} // namespace tumble::app
