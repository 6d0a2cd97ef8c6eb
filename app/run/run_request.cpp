#include "app/run/run_request.h"

#include "app/scene/scene_error.h"
#include "io/bad_input.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace tumble::app {
namespace {

// "R" or "R,P": positive numbers, rad and m.
physics::Tolerance parse_tolerance(const std::string& text) {
    const auto fail = [&] {
        return io::BadInput("--tolerance " + text +
                            ": expected a positive error bound R (rad and m), or R,P: rotation in "
                            "rad, position in m (e.g. 1e-4 or 1e-4,1e-3)");
    };
    const std::size_t comma = text.find(',');
    const auto number = [&](const std::string& part) {
        std::size_t used = 0;
        double v = 0.0;
        try {
            v = std::stod(part, &used);
        } catch (const std::exception&) {
            throw fail();
        }
        if (used != part.size() || !std::isfinite(v) || !(v > 0.0)) throw fail();
        return v;
    };
    const double rotation = number(text.substr(0, comma));
    const double position = comma == std::string::npos ? rotation : number(text.substr(comma + 1));
    return {rotation, position};
}

// "1,2.5" -> {1, 2.5}: finite times >= 0 separated by commas.
std::vector<double> parse_estimate_times(const std::string& list) {
    std::vector<double> times;
    for (std::size_t at = 0; at <= list.size();) {
        const std::size_t comma = std::min(list.find(',', at), list.size());
        const std::string item = list.substr(at, comma - at);
        char* end = nullptr;
        errno = 0;
        const double t = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || errno == ERANGE ||
            !std::isfinite(t) || t < 0.0)
            throw io::BadInput("--error-estimate=" + list +
                               ": expected nothing, or =T1,T2,...: times in seconds >= 0 "
                               "separated by commas (e.g. --error-estimate=1,2.5); got " +
                               (item.empty() ? std::string("an empty time") : "\"" + item + "\""));
        times.push_back(t);
        at = comma + 1;
    }
    return times;
}

std::string seconds(double t) {
    char s[32];
    std::snprintf(s, sizeof s, "%g s", t);
    return s;
}

// The estimate's settings from the options; every time within the run's duration.
void apply_error_estimate(const RunRequest& opts, Scene& scene) {
    ErrorEstimateSettings& e = scene.error_estimate;
    if (opts.no_error_estimate && opts.error_estimate)
        throw io::BadInput("--error-estimate and --no-error-estimate: give one or the other");
    if (opts.no_error_estimate) e = {};
    if (opts.error_estimate) {
        e.on = true;
        if (*opts.error_estimate != kEstimateOn) {
            e.times = parse_estimate_times(*opts.error_estimate);
            e.place = "--error-estimate";
        }
    }
    for (std::size_t i = 0; i < e.times.size(); ++i) {
        if (e.times[i] <= scene.duration) continue;
        const std::string what = "t = " + seconds(e.times[i]) + " is after the end of the run (" +
                                 seconds(scene.duration) + (opts.duration ? ", --duration)" : ")");
        if (e.place == "--error-estimate")
            throw io::BadInput("--error-estimate=" + *opts.error_estimate + ": " + what);
        throw SceneError(scene.source, e.place + "/" + std::to_string(i), what);
    }
}

} // namespace

void apply_request(Scene& scene, const RunRequest& opts) {
    if (opts.integrator) {
        const auto id = physics::integrator_from_name(*opts.integrator);
        if (!id && *opts.integrator != "auto")
            throw SceneError(
                "--integrator", *opts.integrator,
                "unknown integrator; valid integrators: " + physics::integrator_names() + ", auto");
        if (id) scene.world.integrator = *id;
        scene.accuracy.auto_integrator = !id;
    }
    if (opts.tolerance) {
        scene.accuracy.tolerance = parse_tolerance(*opts.tolerance);
        scene.accuracy.tolerance_place = "--tolerance";
        if (!opts.integrator) scene.accuracy.auto_integrator = true;
    }
    if (scene.accuracy.auto_integrator && !scene.accuracy.tolerance)
        throw SceneError("--integrator", "auto",
                         "auto needs a tolerance: --tolerance R[,P] or world.tolerance");
    if (opts.duration) {
        if (!(*opts.duration > 0.0))
            throw SceneError("--duration", std::to_string(*opts.duration),
                             "expected a positive number of seconds");
        scene.duration = *opts.duration;
    }
    if (opts.dt) {
        if (!(*opts.dt > 0.0))
            throw SceneError("--dt", std::to_string(*opts.dt),
                             "expected a positive time step in seconds");
        scene.world.dt = *opts.dt;
    }
    if (opts.contact_tolerance) {
        if (!(*opts.contact_tolerance > 0.0) || !std::isfinite(*opts.contact_tolerance))
            throw SceneError("--contact-tolerance", std::to_string(*opts.contact_tolerance),
                             "expected a positive length in metres");
        scene.world.contact.tolerance = *opts.contact_tolerance;
    }
    apply_error_estimate(opts, scene);
    if (scene.accuracy.tolerance) { // a tolerance is met, and checked, through the estimate
        if (opts.no_error_estimate)
            throw io::BadInput("--no-error-estimate: the tolerance (" +
                               scene.accuracy.tolerance_place +
                               ") is chosen for and checked by the error estimate; give one or "
                               "the other");
        scene.error_estimate.only_for_tolerance = !scene.error_estimate.on;
        scene.error_estimate.on = true;
    }
}

} // namespace tumble::app
