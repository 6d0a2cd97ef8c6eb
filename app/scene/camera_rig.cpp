#include "app/scene/camera_rig_reader.h"

#include "app/scene/body_reference.h"
#include "app/scene/scene_error.h"
#include "app/scene/scene_fields.h"
#include "app/scene/scene_values.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace tumble::app {
namespace {

namespace fields = scene_fields;

glm::dvec3 read_dvec3(const FieldValue& v) {
    const auto a = v.vec3();
    return {a[0], a[1], a[2]};
}

void read_orbit(ObjectReader r, CameraRig& rig) {
    const glm::dvec3 position(rig.base.position), target(rig.base.target);
    rig.center = target;
    if (auto c = r.optional("center")) rig.center = read_dvec3(*c);
    const glm::dvec3 from = position - rig.center;
    rig.radius = std::hypot(from.x, from.y);
    rig.height = from.z;
    rig.start_angle = std::atan2(from.y, from.x);
    if (auto v = r.optional("radius")) rig.radius = v->number();
    if (auto v = r.optional("height")) rig.height = v->number();
    if (auto v = r.optional("start_deg")) rig.start_angle = glm::radians(v->number());
    const FieldValue period = r.field("period");
    rig.period = period.number();
    if (rig.period == 0.0) period.fail("expected a non-zero number of seconds per turn");
    if (rig.radius == 0.0)
        r.fail("the camera position is straight above the orbit centre: give \"radius\"");
    r.finish();
}

void read_follow(ObjectReader r, CameraRig& rig) {
    const FieldValue body = r.field("body");
    rig.follow_name =
        body.value().is_number_integer() ? std::to_string(body.value().get<long>()) : body.string();
    rig.follow_path = body.reader().path();
    rig.offset = glm::dvec3(rig.base.position - rig.base.target);
    if (auto o = r.optional("offset")) rig.offset = read_dvec3(*o);
    if (auto t = r.optional("track")) rig.track = t->boolean();
    if (!rig.track && glm::length(rig.offset) == 0.0)
        r.fail("the camera offset is zero: it would sit inside the body");
    r.finish();
}

void read_path(const FieldValue& path, CameraRig& rig) {
    if (!path.value().is_array() || path.value().size() < 2)
        path.fail("expected an array of at least two keyframes {\"t\", \"position\", \"target\"}");
    for (std::size_t i = 0; i < path.size(); ++i) {
        ObjectReader k(path.at(i).reader(), fields::keyframe());
        CameraKey key;
        const FieldValue t = k.field("t");
        key.t = t.number();
        key.position = read_dvec3(k.field("position"));
        key.target = read_dvec3(k.field("target"));
        key.fov_deg = rig.base.fov_y_deg;
        if (auto f = k.optional("fov_deg")) key.fov_deg = f->number();
        if (!rig.keys.empty() && key.t <= rig.keys.back().t)
            t.fail("expected key times in increasing order");
        if (key.position == key.target) k.fail("camera position and target coincide");
        k.finish();
        rig.keys.push_back(key);
    }
}

void read_auto(const FieldValue& a, CameraRig& rig) {
    rig.mode = CameraRig::Mode::Auto;
    if (a.value().is_boolean()) {
        if (!a.boolean()) rig.mode = CameraRig::Mode::Fixed;
        return;
    }
    ObjectReader r(a.reader(), fields::camera_auto());
    if (auto d = r.optional("direction")) {
        rig.auto_direction = read_dvec3(*d);
        if (glm::length(rig.auto_direction) == 0.0) d->fail("expected a non-zero direction");
    }
    if (auto m = r.optional("margin")) rig.auto_margin = m->number();
    r.finish();
}

} // namespace

void read_camera_rig(JsonReader json, CameraRig& rig) {
    ObjectReader r(json, fields::camera());
    render::Camera& c = rig.base;
    rig.mode = CameraRig::Mode::Fixed; // a camera given; "auto" below may choose it after all
    if (r.has("auto") && (r.has("position") || r.has("target")))
        r.fail("\"auto\" chooses the position and target; give its \"direction\" instead");
    if (auto p = r.optional("position")) c.position = read_glm_vec3(*p);
    if (auto t = r.optional("target")) c.target = read_glm_vec3(*t);
    if (auto u = r.optional("up")) c.up = read_glm_vec3(*u);
    if (auto f = r.optional("fov_deg")) c.fov_y_deg = static_cast<float>(f->number());
    if (glm::length(c.position - c.target) == 0.0f) r.fail("camera position and target coincide");
    if (int(r.has("orbit")) + int(r.has("follow")) + int(r.has("path")) + int(r.has("auto")) > 1)
        r.fail("give at most one of \"orbit\", \"follow\", \"path\" and \"auto\"");
    if (auto a = r.optional("auto")) read_auto(*a, rig);
    if (auto o = r.optional("orbit")) {
        rig.mode = CameraRig::Mode::Orbit;
        read_orbit(ObjectReader(o->reader(), fields::orbit()), rig);
    }
    if (auto f = r.optional("follow")) {
        rig.mode = CameraRig::Mode::Follow;
        read_follow(ObjectReader(f->reader(), fields::follow()), rig);
    }
    if (auto p = r.optional("path")) {
        rig.mode = CameraRig::Mode::Path;
        read_path(*p, rig);
    }
    r.finish();
}

void read_camera_option(const std::string& text, const std::string& option, CameraRig& rig) {
    const auto bad = [&]() -> SceneError {
        return SceneError(option, text,
                          "expected POSITION:TARGET[:FOV] (metres and degrees, e.g. "
                          "1,-2,1.5:0,0,1:40), auto or poinsot");
    };
    if (text == "auto" || text == "poinsot") {
        rig.mode = text == "auto" ? CameraRig::Mode::Auto : CameraRig::Mode::Poinsot;
        rig.auto_direction = glm::dvec3(0.0); // the direction the scene's camera looks from
        return;
    }
    // The ':' parts, each a list of numbers separated by ','.
    std::vector<std::vector<double>> parts(1);
    std::string field;
    for (std::size_t k = 0; k <= text.size(); ++k) {
        if (k < text.size() && text[k] != ':' && text[k] != ',') {
            field += text[k];
            continue;
        }
        char* stop = nullptr;
        const double v = std::strtod(field.c_str(), &stop);
        if (field.empty() || *stop != '\0' || !std::isfinite(v)) throw bad();
        parts.back().push_back(v);
        field.clear();
        if (k < text.size() && text[k] == ':') parts.emplace_back();
    }
    if (parts.size() < 2 || parts.size() > 3 || parts[0].size() != 3 || parts[1].size() != 3 ||
        (parts.size() == 3 && parts[2].size() != 1))
        throw bad();
    std::vector<double> numbers;
    for (const auto& p : parts) numbers.insert(numbers.end(), p.begin(), p.end());
    const std::size_t groups = parts.size();
    const glm::vec3 position(numbers[0], numbers[1], numbers[2]);
    const glm::vec3 target(numbers[3], numbers[4], numbers[5]);
    if (glm::length(position - target) == 0.0f)
        throw SceneError(option, text, "the position and the target coincide");
    if (groups == 3 && !(numbers[6] > 0.0 && numbers[6] < 179.0))
        throw SceneError(option, text, "expected a field of view between 0 and 179 degrees");
    rig.mode = CameraRig::Mode::Fixed;
    rig.base.position = position;
    rig.base.target = target;
    if (groups == 3) rig.base.fov_y_deg = float(numbers[6]);
}

void resolve_followed_body(CameraRig& rig, const std::vector<std::string>& names,
                           const std::string& file) {
    if (rig.mode != CameraRig::Mode::Follow) return;
    rig.follow_body = find_body(names, rig.follow_name, file, rig.follow_path, "follow");
}

} // namespace tumble::app
