#include "app/regression/state_compare.h"

#include "app/run/trajectory_reader.h"
#include "io/bad_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>

namespace tumble::app {
namespace {

using physics::Quat;
using physics::Vec3;

double angle_between(const Quat& a, const Quat& b) {
    const Quat d = a.conjugate() * b;
    return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

// Golden rows by time. Frame times are k * steps_per_frame * h, written with %.17g: the same
// run gives the same bits, so a near-exact match is the right test.
template <class Row>
const Row* at_time(const std::vector<Row>& rows, double t) {
    const auto it = std::lower_bound(rows.begin(), rows.end(), t - 1e-9 * std::max(1.0, t),
                                     [](const Row& r, double x) { return r.t < x; });
    if (it == rows.end() || std::abs(it->t - t) > 1e-9 * std::max(1.0, t)) return nullptr;
    return &*it;
}

struct Golden {
    std::map<std::string, std::vector<StateRow>> bodies; // by name, sorted by t
    std::vector<DiagnosticsRow> diagnostics;             // sorted by t
};

Golden index(Trajectory tr) {
    Golden g;
    for (StateRow& r : tr.states) g.bodies[r.name].push_back(std::move(r));
    auto by_t = [](const auto& a, const auto& b) { return a.t < b.t; };
    for (auto& [name, rows] : g.bodies) std::stable_sort(rows.begin(), rows.end(), by_t);
    g.diagnostics = std::move(tr.diagnostics);
    std::stable_sort(g.diagnostics.begin(), g.diagnostics.end(), by_t);
    return g;
}

Vec3 vector_of(StateQuantity q, const StateRow& r) {
    return q == StateQuantity::kPosition ? r.x : q == StateQuantity::kVelocity ? r.v : r.w;
}
Vec3 vector_of(StateQuantity q, const DiagnosticsRow& r) {
    return q == StateQuantity::kMomentum ? r.p : r.l;
}

// The plotted scalar: the component that differs most at the worst sample; an orientation's
// angle turned since the first golden sample; the energy itself.
template <class Row>
void plot_values(Series& s, const std::vector<const Row*>& actual,
                 const std::vector<const Row*>& golden) {
    if constexpr (std::is_same_v<Row, StateRow>) {
        if (s.quantity == StateQuantity::kOrientation) {
            s.component = "angle turned since the first sample";
            for (std::size_t k = 0; k < actual.size(); ++k) {
                s.actual.push_back(angle_between(golden.front()->q, actual[k]->q));
                s.golden.push_back(angle_between(golden.front()->q, golden[k]->q));
            }
            return;
        }
    } else {
        if (s.quantity == StateQuantity::kEnergy) {
            s.component = "E";
            for (std::size_t k = 0; k < actual.size(); ++k) {
                s.actual.push_back(actual[k]->energy);
                s.golden.push_back(golden[k]->energy);
            }
            return;
        }
    }
    const Vec3 d =
        vector_of(s.quantity, *actual[s.worst]) - vector_of(s.quantity, *golden[s.worst]);
    Eigen::Index axis = 0;
    d.cwiseAbs().maxCoeff(&axis);
    s.component = std::string(1, "xyz"[axis]);
    for (std::size_t k = 0; k < actual.size(); ++k) {
        s.actual.push_back(vector_of(s.quantity, *actual[k])[axis]);
        s.golden.push_back(vector_of(s.quantity, *golden[k])[axis]);
    }
}

template <class Row>
Series make_series(const std::string& body, const Tolerance& tol,
                   const std::vector<std::int64_t>& frames, const std::vector<const Row*>& actual,
                   const std::vector<const Row*>& golden) {
    Series s;
    s.body = body;
    s.quantity = tol.quantity;
    s.tolerance = tol.absolute;
    s.frames = frames;
    for (std::size_t k = 0; k < actual.size(); ++k) {
        const double d = deviation(tol.quantity, *actual[k], *golden[k]);
        s.t.push_back(actual[k]->t);
        s.deviation.push_back(d);
        if (s.first_out < 0 && !(d <= tol.absolute)) s.first_out = static_cast<int>(k);
        if (d > s.deviation[s.worst]) s.worst = k;
    }
    plot_values(s, actual, golden);
    return s;
}

std::string when(const Series& s, std::size_t k) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "t = %.6g s (frame %lld)", s.t[k],
                  static_cast<long long>(s.frames[k]));
    return buf;
}

std::string what(const Series& s) {
    return (s.body.empty() ? std::string() : "body \"" + s.body + "\" ") +
           quantity_name(s.quantity);
}

std::string failure_line(const Series& s) {
    const char* unit = quantity_unit(s.quantity);
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "%s: out of tolerance from %s by %.3g %s (tolerance %.3g %s); largest %.3g %s at "
                  "%s",
                  what(s).c_str(), when(s, std::size_t(s.first_out)).c_str(),
                  s.deviation[std::size_t(s.first_out)], unit, s.tolerance, unit,
                  s.deviation[s.worst], unit, when(s, s.worst).c_str());
    return buf;
}

} // namespace

double Series::ratio() const {
    const double d = deviation.empty() ? 0.0 : deviation[worst];
    if (tolerance > 0) return d / tolerance;
    return d > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

double deviation(StateQuantity q, const StateRow& a, const StateRow& g) {
    if (q == StateQuantity::kOrientation) return angle_between(g.q, a.q);
    return (vector_of(q, a) - vector_of(q, g)).norm();
}

double deviation(StateQuantity q, const DiagnosticsRow& a, const DiagnosticsRow& g) {
    if (q == StateQuantity::kEnergy) return std::abs(a.energy - g.energy);
    return (vector_of(q, a) - vector_of(q, g)).norm();
}

namespace {

// The golden rows matching the samples, or the reason there are none.
struct Matched {
    std::vector<std::vector<const StateRow*>> bodies; // [body][sample]
    std::vector<const DiagnosticsRow*> diagnostics;   // [sample]
    std::string missing;
};

Matched match(const StateCheck& check, const StateOutcome& out, const Golden& g) {
    Matched m;
    m.bodies.resize(check.bodies.size());
    const bool scene_quantity =
        std::any_of(check.quantities.begin(), check.quantities.end(),
                    [](const Tolerance& t) { return !per_body(t.quantity); });
    for (const Sample& s : out.samples) {
        const double t = s.diagnostics.t;
        char at[80];
        std::snprintf(at, sizeof at, " at t = %.6g s (frame %lld)", t,
                      static_cast<long long>(s.frame));
        for (std::size_t b = 0; b < check.bodies.size(); ++b) {
            const auto it = g.bodies.find(check.bodies[b]);
            const StateRow* row = it == g.bodies.end() ? nullptr : at_time(it->second, t);
            if (!row && m.missing.empty())
                m.missing =
                    "the golden trajectory has no row for body \"" + check.bodies[b] + "\"" + at;
            m.bodies[b].push_back(row);
        }
        const DiagnosticsRow* d = scene_quantity ? at_time(g.diagnostics, t) : &s.diagnostics;
        if (!d && m.missing.empty())
            m.missing = "the golden diagnostics have no row" + std::string(at);
        m.diagnostics.push_back(d);
    }
    return m;
}

void summarise(CheckResult& r) {
    const std::vector<Series>& all = r.state_outcome.series;
    std::vector<const Series*> failed;
    for (const Series& s : all)
        if (!s.passed()) failed.push_back(&s);
    r.passed = failed.empty();
    if (!r.passed) {
        std::stable_sort(failed.begin(), failed.end(), [](const Series* a, const Series* b) {
            return a->t[std::size_t(a->first_out)] < b->t[std::size_t(b->first_out)];
        });
        r.summary = failure_line(*failed.front());
        if (failed.size() > 1)
            r.summary += "; " + std::to_string(failed.size() - 1) + " more out of tolerance";
        if (failed.size() > 1)
            for (const Series* s : failed) r.details.push_back(failure_line(*s));
        return;
    }
    const auto closest =
        std::max_element(all.begin(), all.end(),
                         [](const Series& a, const Series& b) { return a.ratio() < b.ratio(); });
    char buf[256];
    std::snprintf(
        buf, sizeof buf,
        "%zu samples, %zu series within tolerance (closest: %s at %.3g%% of its tolerance)",
        r.state_outcome.samples.size(), all.size(), what(*closest).c_str(),
        100.0 * closest->ratio());
    r.summary = buf;
}

} // namespace

void judge_states(const StateCheck& check, CheckResult& r) {
    std::error_code ec;
    if (!std::filesystem::exists(check.golden, ec)) {
        r.golden_missing = true;
        r.summary = "no golden trajectory " + check.golden.string();
        return;
    }
    Golden g;
    try {
        const bool scene_quantity =
            std::any_of(check.quantities.begin(), check.quantities.end(),
                        [](const Tolerance& t) { return !per_body(t.quantity); });
        g = index(read_trajectory(check.golden, scene_quantity ? check.golden_diagnostics()
                                                               : std::filesystem::path()));
    } catch (const io::BadInput& e) {
        r.summary = std::string("cannot read the golden trajectory: ") + e.what();
        return;
    }
    StateOutcome& out = r.state_outcome;
    const Matched m = match(check, out, g);
    if (!m.missing.empty()) {
        r.summary = m.missing;
        return;
    }
    std::vector<const StateRow*> actual(out.samples.size());
    std::vector<const DiagnosticsRow*> actual_d(out.samples.size());
    for (std::size_t k = 0; k < out.samples.size(); ++k) actual_d[k] = &out.samples[k].diagnostics;
    for (std::size_t b = 0; b < check.bodies.size(); ++b) {
        for (std::size_t k = 0; k < out.samples.size(); ++k) actual[k] = &out.samples[k].bodies[b];
        for (const Tolerance& tol : check.quantities)
            if (per_body(tol.quantity))
                out.series.push_back(
                    make_series(check.bodies[b], tol, check.frames, actual, m.bodies[b]));
    }
    for (const Tolerance& tol : check.quantities)
        if (!per_body(tol.quantity))
            out.series.push_back(
                make_series(std::string(), tol, check.frames, actual_d, m.diagnostics));
    summarise(r);
}

} // namespace tumble::app
