// Scene file -> Scene. The format is documented in docs/scene-format.md; keep the two in step.
#include "app/scene/assets.h"
#include "app/scene/body_loader.h"
#include "app/scene/body_reference.h"
#include "app/scene/camera_rig_reader.h"
#include "app/scene/scene.h"

#include "app/scene/input_file.h"
#include "app/scene/scene_check.h"
#include "app/scene/scene_fields.h"
#include "app/scene/scene_values.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace tumble::app {
namespace {

constexpr int kFormatVersion = 1;
namespace fields = scene_fields;

// world.tolerance: one bound for both (rad and m), or {"rotation": rad, "position": m}.
physics::Tolerance read_tolerance(JsonReader r) {
    if (r.value().is_number()) {
        const double both = r.positive("a positive tolerance");
        return {both, both};
    }
    ObjectReader o(r, fields::tolerance());
    const physics::Tolerance t{o.field("rotation").number(), o.field("position").number()};
    o.finish();
    return t;
}

// world.error_estimate: true, or {"times": [1, 2.5]} (times within the duration, read before it).
void read_error_estimate(FieldValue& v, Scene& s) {
    ErrorEstimateSettings& e = s.error_estimate;
    if (v.value().is_boolean()) {
        e.on = v.boolean();
        return;
    }
    if (!v.value().is_object())
        v.fail("expected true, false or {\"times\": [t1, t2, ...]}, got " +
               describe_json(v.value()));
    ObjectReader r(v.reader(), fields::error_estimate());
    e.on = true;
    const FieldValue times = r.field("times");
    e.place = times.reader().path();
    for (std::size_t i = 0; i < times.size(); ++i) {
        const FieldValue t = times.at(i);
        e.times.push_back(t.number());
        if (e.times.back() > s.duration) {
            char duration[32];
            std::snprintf(duration, sizeof duration, "%g", s.duration);
            t.fail("expected a time within the duration (" + std::string(duration) + " s), got " +
                   describe_json(t.value()) + " s");
        }
    }
    r.finish();
}

void read_world(ObjectReader r, Scene& s) {
    if (auto g = r.optional("gravity")) s.world.gravity = read_vec3(*g);
    if (auto dt = r.optional("dt")) s.world.dt = dt->number();
    if (auto d = r.optional("duration")) s.duration = d->number();
    if (auto i = r.optional("integrator")) {
        const std::string name = i->string();
        const auto id = physics::integrator_from_name(name);
        if (!id && name != "auto")
            i->fail("unknown integrator " + describe_json(i->value()) +
                    "; valid integrators: " + physics::integrator_names() + ", auto");
        if (id) s.world.integrator = *id;
        s.accuracy.auto_integrator = !id;
    }
    if (auto t = r.optional("tolerance")) {
        s.accuracy.tolerance = read_tolerance(t->reader());
        s.accuracy.tolerance_place = t->reader().path();
    }
    if (s.accuracy.auto_integrator && !s.accuracy.tolerance)
        r.fail("world.integrator \"auto\" needs world.tolerance (a number, or {\"rotation\": "
               "rad, \"position\": m}): the error it must meet");
    physics::ContactSettings& c = s.world.contact; // physics/contact_model.h
    if (auto v = r.optional("sleeping")) c.sleeping = v->boolean();
    if (auto v = r.optional("substeps")) c.substeps = v->integer();
    if (auto v = r.optional("iterations")) c.iterations = v->integer();
    if (auto v = r.optional("contact_tolerance")) c.tolerance = v->number();
    if (auto v = r.optional("restitution_threshold")) c.restitution_threshold = v->number();
    if (auto v = r.optional("parallel_min_bodies")) c.parallel_min_bodies = v->integer();
    if (auto v = r.optional("error_estimate")) read_error_estimate(*v, s);
    r.finish();
}

void read_light(ObjectReader r, render::Light& l) {
    if (auto d = r.optional("direction")) {
        l.direction = read_glm_vec3(*d);
        if (glm::length(l.direction) == 0.0f) d->fail("expected a non-zero light direction");
    }
    if (auto c = r.optional("color")) l.color = read_color(c->reader());
    if (auto a = r.optional("ambient")) l.ambient = static_cast<float>(a->number());
    if (auto a = r.optional("angle")) l.angle_deg = static_cast<float>(a->number());
    r.finish();
}

// render.chart: {"quantities": ["energy", "w_body"], "body": "book", "window": 5}
void read_chart(ObjectReader r, RenderSettings& rs) {
    const FieldValue q = r.field("quantities");
    rs.chart.clear();
    for (std::size_t i = 0; i < q.size(); ++i)
        rs.chart.push_back(*parse_quantity(q.at(i).choice()));
    if (auto b = r.optional("body")) rs.chart_body = {b->string(), b->reader().path()};
    if (auto w = r.optional("window")) rs.chart_window = w->number();
    r.finish();
}

// render.trails: true, or {"seconds": 3, "axis": "x"}
void read_trails(FieldValue& v, RenderSettings& rs) {
    if (v.value().is_boolean()) {
        rs.trails = v.boolean();
        return;
    }
    ObjectReader r(v.reader(), scene_fields::trails());
    rs.trails = true;
    if (auto s = r.optional("seconds")) rs.trail_seconds = s->number();
    if (auto a = r.optional("axis")) rs.trail_axis = a->choice()[0] - 'x';
    r.finish();
}

void read_render(ObjectReader r, RenderSettings& rs) {
    if (auto w = r.optional("width")) rs.width = w->integer();
    if (auto h = r.optional("height")) rs.height = h->integer();
    if (auto f = r.optional("fps")) rs.fps = f->integer();
    if (auto c = r.optional("camera")) read_camera_rig(c->reader(), rs.camera);
    if (auto l = r.optional("light"))
        read_light(ObjectReader(l->reader(), fields::light()), rs.light);
    if (auto b = r.optional("background")) rs.background = read_color(b->reader());
    if (auto v = r.optional("shadows")) rs.shadows = v->boolean();
    if (auto v = r.optional("soft_shadows")) rs.soft_shadows = v->boolean();
    if (auto v = r.optional("ambient_occlusion")) rs.ambient_occlusion = v->boolean();
    if (auto v = r.optional("reflections")) rs.reflections = v->boolean();
    if (auto v = r.optional("antialiasing")) rs.antialiasing = v->boolean();
    if (auto v = r.optional("overlay")) rs.overlay = v->boolean();
    if (auto v = r.optional("axes")) rs.axes = v->boolean();
    if (auto v = r.optional("vectors")) rs.vectors = v->boolean();
    if (auto c = r.optional("chart"))
        read_chart(ObjectReader(c->reader(), scene_fields::chart()), rs);
    if (auto t = r.optional("trails")) read_trails(*t, rs);
    if (auto p = r.optional("poinsot")) rs.poinsot = {p->string(), p->reader().path()};
    if (auto o = r.optional("overlay_body")) rs.overlay_body = {o->string(), o->reader().path()};
    r.finish();
}

// dampers: [{"bodies": ["satellite", "rotor"], "coefficient": 0.012}] (physics/damper.h), read
// once the bodies' names are known.
void read_dampers(const FieldValue& list, const std::vector<std::string>& names, Scene& s) {
    for (std::size_t i = 0; i < list.size(); ++i) {
        ObjectReader r(list.at(i).reader(), fields::damper());
        const FieldValue bodies = r.field("bodies");
        int index[2] = {0, 0};
        for (std::size_t k = 0; k < bodies.size(); ++k) {
            const FieldValue b = bodies.at(k);
            index[k] =
                find_body(names, b.string(), s.source, b.reader().path(), "couple with a damper");
        }
        if (index[0] == index[1])
            bodies.fail("expected two different bodies, got \"" + names[std::size_t(index[0])] +
                        "\" twice");
        const auto is_static = [&](int b) {
            return s.bodies[std::size_t(b)].motion == physics::Motion::Static;
        };
        if (is_static(index[0]) && is_static(index[1]))
            bodies.fail("expected at least one body that moves: both are static");
        const double c = r.field("coefficient").number();
        r.finish();
        s.world.dampers.push_back({index[0], index[1], c});
    }
}

} // namespace

Scene load_scene(const std::string& text, const std::string& source) {
    const nlohmann::json root = parse_json(text, source);
    if (!root.is_object())
        JsonReader(root, source, "").fail("expected a scene object { \"format_version\": 1, ... }");
    ObjectReader r(JsonReader(root, source, ""), fields::scene());
    const FieldValue format = r.field("format_version");
    // Read wider than the table's [1, 1], to say which version this tumble reads.
    const int version = format.reader().integer(1, 1000, "the scene format version");
    if (version != kFormatVersion)
        format.fail("this tumble reads format_version " + std::to_string(kFormatVersion) +
                    ", got " + std::to_string(version));
    Scene s;
    s.source = source;
    ContentHash inputs; // the scene's text, then each mesh file's
    inputs.add(text);
    if (auto t = r.optional("title")) s.title = t->string();
    if (auto w = r.optional("world")) read_world(ObjectReader(w->reader(), fields::world()), s);
    if (auto rs = r.optional("render"))
        read_render(ObjectReader(rs->reader(), fields::render()), s.render);
    const FieldValue bodies = r.field("bodies");
    const std::size_t n = bodies.size();
    s.bodies.resize(n);
    s.looks.resize(n);
    ShapeContext shapes{source, &s.meshes, {}, &inputs};
    for (std::size_t i = 0; i < n; ++i)
        read_body(bodies.at(i).reader(), static_cast<int>(i), shapes, s.bodies[i], s.looks[i]);
    std::vector<std::string> names;
    for (const BodyLook& look : s.looks) names.push_back(look.name);
    if (auto d = r.optional("dampers")) read_dampers(*d, names, s);
    r.finish();
    s.content_hash = inputs.value();
    resolve_followed_body(s.render.camera, names, source);
    resolve_render_bodies(s);
    // Physics validation, mapped to JSON paths; then what is legal but probably unintended.
    const CheckedStart start = build_checked(s, s.world.dt);
    s.warnings = initial_state_warnings(s, start.model, start.state);
    return s;
}

std::string scene_name(const Scene& scene) {
    std::string source = scene.source;
    if (source.starts_with("builtin:")) source.erase(0, 8);
    const std::string stem = std::filesystem::path(source).stem().string();
    return stem.empty() ? "tumble" : stem;
}

std::vector<std::string> builtin_scene_names() {
    std::vector<std::string> out;
    for (std::string_view name : assets::names()) {
        std::string n(name);
        if (n.size() > 5 && n.ends_with(".json")) out.push_back(n.substr(0, n.size() - 5));
    }
    std::stable_partition(out.begin(), out.end(),
                          [](const std::string& n) { return n.find('/') == std::string::npos; });
    return out;
}

Scene load_scene_argument(const std::string& argument) {
    std::string arg = argument.empty() ? "default" : argument;
    // "builtin:NAME", as messages and summaries name a built-in scene, means that one only.
    const bool builtin_only = arg.starts_with("builtin:");
    if (builtin_only) arg.erase(0, 8);
    std::error_code ec;
    if (!builtin_only && std::filesystem::is_regular_file(arg, ec))
        return load_scene(read_input_file(arg, "scene"), arg);
    const std::string file = arg.ends_with(".json") ? arg : arg + ".json";
    // Built in by its whole name: "default.json", "lessons/top_precession.json".
    const std::string_view builtin = assets::find(file);
    if (!builtin.empty()) return load_scene(std::string(builtin), "builtin:" + file);
    std::string names;
    for (const std::string& n : builtin_scene_names()) names += (names.empty() ? "" : ", ") + n;
    throw SceneError(arg, "file",
                     std::filesystem::exists(arg, ec)
                         ? "not a regular file"
                         : "no such file, and no built-in scene of that name "
                           "(built-in scenes: " +
                               names + ")");
}

} // namespace tumble::app
