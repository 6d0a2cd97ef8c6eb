#include "app/run/trajectory_rows.h"

#include "physics/diagnostics.h"

namespace tumble::app {
namespace {

// CSV field: quoted, with inner quotes doubled (RFC 4180).
std::string csv_quote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

} // namespace

StateRow state_row(const physics::Model& m, const physics::State& s, int body,
                   const std::string& name) {
    const physics::Pose p = physics::body_pose(m, s, body);
    return {s.step, s.time(m), body, name, p.position, p.orientation, s.v[body], s.w[body]};
}

DiagnosticsRow diagnostics_row(const physics::Model& m, const physics::State& s) {
    const physics::Diagnostics d = physics::diagnose(m, s);
    return {s.step,     s.time(m),         d.kinetic(),       d.potential,
            d.energy(), d.linear_momentum, d.angular_momentum};
}

void print_row(std::FILE* out, const StateRow& r) {
    std::fprintf(out,
                 "%lld,%.17g,%d,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                 "%.17g,%.17g,%.17g\n",
                 static_cast<long long>(r.step), r.t, r.body, csv_quote(r.name).c_str(), r.x.x(),
                 r.x.y(), r.x.z(), r.q.w(), r.q.x(), r.q.y(), r.q.z(), r.v.x(), r.v.y(), r.v.z(),
                 r.w.x(), r.w.y(), r.w.z());
}

void print_fields(std::FILE* out, const DiagnosticsRow& r) {
    std::fprintf(out, "%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g",
                 static_cast<long long>(r.step), r.t, r.kinetic, r.potential, r.energy, r.p.x(),
                 r.p.y(), r.p.z(), r.l.x(), r.l.y(), r.l.z());
}

void print_row(std::FILE* out, const DiagnosticsRow& r) {
    print_fields(out, r);
    std::fputc('\n', out);
}

} // namespace tumble::app
