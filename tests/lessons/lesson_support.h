#pragma once
// What the lessons' tests share (docs/lessons/): a lesson's scene run as the app runs it (its file
// through the real loader, the step the timeline gives, app::Simulation's stepping), and the
// numbers a lesson quotes, read from its "Numbers, checked" table so that the text and the test
// cannot disagree.
//
// The table's rows look like
//   | `flip_interval` | 3.72 | s | time between two flips | `Lessons.IntermediateAxis...` |
// and a quoted value holds a measurement to the digits shown: expect_quoted() asserts that the
// measured value rounds to it (within half a unit of its last digit), and that the same string
// appears in the lesson's prose as well as in the table.
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "physics/state.h"
#include "support/cli_runner.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace tumble::test {

inline std::filesystem::path lesson_file(const std::string& name) {
    return std::filesystem::path(TUMBLE_SOURCE_DIR) / "docs/lessons" / name;
}

// assets/scenes/lessons/<name>.json through the loader, as `tumble render FILE` reads it.
inline app::Scene lesson_scene(const std::string& name) {
    const auto path =
        std::filesystem::path(TUMBLE_SOURCE_DIR) / "assets/scenes/lessons" / (name + ".json");
    return app::load_scene(read_text(path), path.string());
}

// The simulation `tumble render` and `tumble simulate` step: the scene's dt as the timeline
// adjusts it to the frame rate, and the integrator `integrator` if given (--integrator).
inline app::Simulation lesson_simulation(app::Scene scene,
                                         std::optional<physics::Integrator> integrator = {},
                                         std::optional<double> dt = {}) {
    if (integrator) scene.world.integrator = *integrator;
    const app::Timeline tl =
        app::make_timeline(dt.value_or(scene.world.dt), scene.duration, scene.render.fps);
    return app::make_simulation(scene, dt ? *dt : tl.h);
}

inline physics::Integrator integrator_named(const std::string& name) {
    return *physics::integrator_from_name(name);
}

// The index of the body the scene names `name` (the same in the Model built from it).
inline int body_index(const app::Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.looks.size(); ++i)
        if (scene.looks[i].name == name) return static_cast<int>(i);
    ADD_FAILURE() << "the scene has no body \"" << name << "\"";
    return 0;
}

// Principal moments of a box body from the box formula I1 = m (b^2 + c^2) / 12 (and cyclic), with
// b, c the other two edges: independent of the model's own mass properties.
inline physics::Vec3 box_moments(const physics::BodyDef& b) {
    const physics::Vec3 s = 2.0 * b.shape.half_extents;
    return {b.mass * (s.y() * s.y() + s.z() * s.z()) / 12,
            b.mass * (s.x() * s.x() + s.z() * s.z()) / 12,
            b.mass * (s.x() * s.x() + s.y() * s.y()) / 12};
}

// The value string of `key` in the lesson's table ("" if absent).
inline std::string quoted_text(const std::string& lesson, const std::string& key) {
    const std::string text = read_text(lesson_file(lesson));
    const std::string start = "| `" + key + "` | ";
    const std::size_t at = text.find(start);
    if (at == std::string::npos) return "";
    const std::size_t from = at + start.size();
    std::string value = text.substr(from, text.find(" |", from) - from);
    return value;
}

// The keys of the lesson's "Numbers, checked" table (the last section), in order.
inline std::vector<std::string> table_keys(const std::string& lesson) {
    std::vector<std::string> keys;
    const std::string text = read_text(lesson_file(lesson));
    const std::size_t at = text.find("\n## Numbers, checked");
    if (at == std::string::npos) return keys;
    std::istringstream in(text.substr(at));
    for (std::string line; std::getline(in, line);)
        if (line.starts_with("| `")) keys.push_back(line.substr(3, line.find('`', 3) - 3));
    return keys;
}

// Half a unit of the last digit of a decimal number as written: "3.72" -> 0.005, "1.2e-05" ->
// 5e-07, "61" -> 0.5.
inline double half_last_digit(const std::string& v) {
    const std::size_t e = v.find_first_of("eE");
    const std::string mantissa = v.substr(0, e);
    const int exponent = e == std::string::npos ? 0 : std::stoi(v.substr(e + 1));
    const std::size_t dot = mantissa.find('.');
    const int decimals = dot == std::string::npos ? 0 : int(mantissa.size() - dot - 1);
    return 0.5 * std::pow(10.0, exponent - decimals);
}

// The lesson quotes `measured` for `key`, rounded to the digits it shows, and says it in its prose
// too (the string appears at least twice in the file).
inline void expect_quoted(const std::string& lesson, const std::string& key, double measured) {
    const std::string v = quoted_text(lesson, key);
    std::printf("[lesson] %s %s: quoted %s, measured %.9g\n", lesson.c_str(), key.c_str(),
                v.c_str(), measured);
    ASSERT_FALSE(v.empty()) << lesson << " has no row `" << key << "` in its Numbers table";
    double quoted = 0;
    try {
        quoted = std::stod(v);
    } catch (const std::exception&) {
        FAIL() << "docs/lessons/" << lesson << ": `" << key << "` quotes \"" << v
               << "\", not a number";
    }
    const double tolerance = half_last_digit(v) * (1 + 1e-9);
    EXPECT_LE(std::abs(measured - quoted), tolerance)
        << "docs/lessons/" << lesson << " quotes " << key << " = " << v << " but the test measures "
        << measured;
    const std::string text = read_text(lesson_file(lesson));
    const std::size_t first = text.find(v);
    EXPECT_NE(text.find(v, first + 1), std::string::npos)
        << "docs/lessons/" << lesson << ": " << v << " (" << key
        << ") is in the table but not in the text";
}

// The angle between two vectors, accurate near 0 and pi (acos of a dot product is not: it
// resolves no angle below about 1e-8).
inline double angle_between(const physics::Vec3& a, const physics::Vec3& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Least-squares slope of y against x.
inline double slope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Adds the angle `a` to a running unwrapped angle whose last raw value was `last`.
inline double unwrap(double unwrapped, double& last, double a) {
    unwrapped += std::remainder(a - last, 2.0 * M_PI);
    last = a;
    return unwrapped;
}

// The two turns of a torque-free symmetric body, fitted over a run: (w1, w2) about the body's axis
// as seen from the body, and the axis about the fixed L as seen from the room (lessons 1 and 8).
class TurnRates {
  public:
    explicit TurnRates(const physics::Vec3& l)
        : u_(l.normalized().unitOrthogonal()), v_(l.normalized().cross(u_)) {}
    // At time t: w in the body's axes, and the body's axis in the world.
    void add(double t, const physics::Vec3& w_body, const physics::Vec3& axis) {
        const double b = std::atan2(w_body.y(), w_body.x()),
                     r = std::atan2(axis.dot(v_), axis.dot(u_));
        if (t_.empty()) last_body_ = b, last_room_ = r;
        body_ = unwrap(body_, last_body_, b);
        room_ = unwrap(room_, last_room_, r);
        t_.push_back(t);
        body_angle_.push_back(body_);
        room_angle_.push_back(room_);
    }
    double body() const { return slope(t_, body_angle_); }
    double room() const { return slope(t_, room_angle_); }

  private:
    physics::Vec3 u_, v_;
    std::vector<double> t_, body_angle_, room_angle_;
    double body_ = 0, room_ = 0, last_body_ = 0, last_room_ = 0;
};

} // namespace tumble::test
