#include "app/plot/series.h"

#include "io/bad_input.h"

#include <cmath>
#include <cstdio>

namespace tumble::app::plot {
namespace {

std::string names_of(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "\"" : ", \"") + n + "\"";
    return out;
}

// The body index named `body` in a run's states (the rows of its first step hold every body).
int body_index(const Run& run, const std::string& body) {
    std::vector<std::string> seen;
    int found = -1;
    for (const StateRow& r : run.states) {
        if (r.step != run.states.front().step) break;
        seen.push_back(r.name);
        if (r.name != body) continue;
        if (found >= 0)
            throw io::BadInput("--bodies " + body + ": two bodies of " + run.files.states.string() +
                               " are named \"" + body + "\" (bodies " + std::to_string(found) +
                               " and " + std::to_string(r.body) + ")");
        found = r.body;
    }
    if (found < 0)
        throw io::BadInput("--bodies " + body + ": no body of that name in " +
                           run.files.states.string() + " (its bodies: " + names_of(seen) + ")");
    return found;
}

// A run of another scene would be drawn with the wrong masses: its bodies must be the scene's.
void check_run_matches_scene(const Run& run, const PlotRequest& req) {
    std::vector<std::string> names;
    for (const StateRow& r : run.states) {
        if (r.step != run.states.front().step) break;
        names.push_back(r.name);
    }
    if (names != req.scene_bodies)
        throw io::BadInput("--scene " + req.scene_source + ": its bodies (" +
                           names_of(req.scene_bodies) + ") are not those of the run " +
                           run.files.states.string() + " (" + names_of(names) + ")");
}

// (E(t) - E(0)) / |E(0)| in place.
void to_drift(Series& s, const std::string& of) {
    if (s.points.empty()) return;
    const double e0 = s.points.front().second;
    if (e0 == 0.0)
        throw io::BadInput("--quantity energy_drift: the energy of " + of +
                           " is 0 at the first row, so no drift relative to it exists; plot "
                           "energy instead");
    for (auto& [t, e] : s.points) e = (e - e0) / std::abs(e0);
}

std::string title(const Run& run, const std::string& body, Quantity q, std::string_view component,
                  bool several_quantities) {
    std::string t = run.label;
    if (!body.empty()) t += ": " + body;
    if (!component.empty())
        t += ": " + std::string(component);
    else if (several_quantities)
        t += ": " + std::string(quantity_info(q).name);
    return t;
}

// One series per component of q, from the rows of one body (body >= 0) or the diagnostics.
std::vector<Series> series_of(const Run& run, const std::string& body, int index, Quantity q,
                              const PlotRequest& req) {
    const bool several = req.quantities.size() > 1;
    const std::vector<std::string_view> names = series_names(q);
    const std::size_t n = names.size();
    std::vector<Series> out(n);
    for (std::size_t c = 0; c < n; ++c) out[c].title = title(run, body, q, names[c], several);
    const auto add = [&](double t, const std::vector<double>& values) {
        for (std::size_t c = 0; c < n; ++c) out[c].points.emplace_back(t, values[c]);
    };
    if (index >= 0) {
        for (const StateRow& r : run.states)
            if (r.body == index) add(r.t, body_values(q, req.model, r));
    } else {
        for (const DiagnosticsRow& r : run.diagnostics) add(r.t, scene_values(q, r));
    }
    if (quantity_info(q).drift)
        to_drift(out[0], index >= 0 ? body + " in " + run.files.states.string()
                                    : run.files.diagnostics.string());
    return out;
}

} // namespace

void check_request(const PlotRequest& req) {
    const QuantityInfo& first = quantity_info(req.quantities.front());
    for (Quantity q : req.quantities) {
        const QuantityInfo& info = quantity_info(q);
        const std::string option = "--quantity " + std::string(info.name);
        if (info.unit != first.unit)
            throw io::BadInput(option + ": its unit (" + std::string(info.unit) + ") is not " +
                               std::string(first.name) + "'s (" + std::string(first.unit) +
                               "); one figure has one axis: draw them in two figures");
        if (req.bodies.empty() && !info.of_scene)
            throw io::BadInput(option + ": a body's quantity: name the body with --bodies");
        if (req.bodies.empty() && !in_diagnostics_table(q))
            throw io::BadInput(option + ": the diagnostics table holds no scene total of it; "
                                        "name the bodies with --bodies (and the scene with "
                                        "--scene), or draw it with `tumble render --chart`");
        if (!req.bodies.empty() && needs_scene(q) && !req.model)
            throw io::BadInput(option + " of a body needs its mass and inertia: name the run's "
                                        "scene with --scene");
    }
}

std::vector<Series> make_series(const std::vector<Run>& runs, const PlotRequest& req) {
    check_request(req);
    std::vector<Series> out;
    for (const Run& run : runs) {
        if (reads_states(req) && run.states.empty())
            throw io::BadInput(run.files.states.string() + ": no rows below the header");
        if (reads_diagnostics(req) && run.diagnostics.empty())
            throw io::BadInput(run.files.diagnostics.string() + ": no rows below the header");
        if (req.model && reads_states(req)) check_run_matches_scene(run, req);
        const std::vector<std::string> bodies =
            req.bodies.empty() ? std::vector<std::string>{""} : req.bodies;
        for (const std::string& body : bodies) {
            const int index = body.empty() ? -1 : body_index(run, body);
            for (Quantity q : req.quantities)
                for (Series& s : series_of(run, body, index, q, req)) out.push_back(std::move(s));
        }
    }
    return out;
}

} // namespace tumble::app::plot
