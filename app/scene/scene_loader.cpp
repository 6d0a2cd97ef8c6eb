// Scene file -> Scene. The format is documented in docs/scene-format.md; keep the two in step.
#include "app/scene/assets.h"
#include "app/scene/body_loader.h"
#include "app/scene/scene.h"

#include "app/scene/input_file.h"
#include "app/scene/scene_check.h"
#include "app/scene/scene_values.h"

#include <filesystem>

namespace tumble::app {
namespace {

constexpr int kFormatVersion = 1;

void read_world(JsonReader r, Scene& s) {
    if (auto g = r.optional("gravity"))
        s.world.gravity = read_vec3(*g, "gravity [x, y, z] in m/s^2");
    if (auto dt = r.optional("dt")) s.world.dt = dt->positive("a positive time step in seconds");
    if (auto d = r.optional("duration")) s.duration = d->positive("a positive duration in seconds");
    if (auto i = r.optional("integrator")) {
        const std::string name = i->string();
        const auto id = physics::integrator_from_name(name);
        if (!id)
            i->fail("unknown integrator " + describe_json(i->value()) +
                    "; valid integrators: " + physics::integrator_names());
        s.world.integrator = *id;
    }
    physics::ContactSettings& c = s.world.contact; // physics/contact_model.h
    if (auto v = r.optional("sleeping")) c.sleeping = v->boolean();
    if (auto v = r.optional("substeps"))
        c.substeps = v->integer(0, 64, "contact substeps per step (0: automatic)");
    if (auto v = r.optional("iterations"))
        c.iterations = v->integer(1, 64, "contact solve sweeps per substep, 1..64");
    if (auto v = r.optional("restitution_threshold"))
        c.restitution_threshold = v->non_negative("an impact speed >= 0 in m/s");
    if (auto v = r.optional("parallel_min_bodies"))
        c.parallel_min_bodies =
            v->integer(0, 1 << 30, "a body count >= 0 from which --threads is used");
    r.finish();
}

void read_light(JsonReader r, render::Light& l) {
    if (auto d = r.optional("direction")) {
        l.direction = read_glm_vec3(*d, "the direction the light travels [x, y, z]");
        if (glm::length(l.direction) == 0.0f) d->fail("expected a non-zero light direction");
    }
    if (auto c = r.optional("color")) l.color = read_color(*c);
    if (auto a = r.optional("ambient"))
        l.ambient = static_cast<float>(a->non_negative("a non-negative ambient fraction"));
    if (auto a = r.optional("angle")) {
        const double deg = a->non_negative("the light's angular diameter in degrees, 0 to 20");
        if (deg > 20.0) a->fail("expected the light's angular diameter in degrees, 0 to 20");
        l.angle_deg = static_cast<float>(deg);
    }
    r.finish();
}

void read_render(JsonReader r, RenderSettings& rs) {
    if (auto w = r.optional("width"))
        rs.width = w->integer(rs.kMinSide, rs.kMaxWidth, "an image width in pixels");
    if (auto h = r.optional("height"))
        rs.height = h->integer(rs.kMinSide, rs.kMaxHeight, "an image height in pixels");
    if (auto f = r.optional("fps")) rs.fps = f->integer(1, 1000, "frames per second");
    if (auto c = r.optional("camera")) read_camera_rig(*c, rs.camera);
    if (auto l = r.optional("light")) read_light(*l, rs.light);
    if (auto b = r.optional("background")) rs.background = read_color(*b);
    if (auto v = r.optional("shadows")) rs.shadows = v->boolean();
    if (auto v = r.optional("soft_shadows")) rs.soft_shadows = v->boolean();
    if (auto v = r.optional("ambient_occlusion")) rs.ambient_occlusion = v->boolean();
    if (auto v = r.optional("reflections")) rs.reflections = v->boolean();
    if (auto v = r.optional("antialiasing")) rs.antialiasing = v->boolean();
    if (auto v = r.optional("overlay")) rs.overlay = v->boolean();
    if (auto v = r.optional("axes")) rs.axes = v->boolean();
    if (auto v = r.optional("vectors")) rs.vectors = v->boolean();
    r.finish();
}

} // namespace

Scene load_scene(const std::string& text, const std::string& source) {
    const nlohmann::json root = parse_json(text, source);
    JsonReader r(root, source, "");
    if (!root.is_object()) r.fail("expected a scene object { \"format_version\": 1, ... }");
    const int version = r.field("format_version").integer(1, 1000, "the scene format version");
    if (version != kFormatVersion)
        r.field("format_version")
            .fail("this tumble reads format_version " + std::to_string(kFormatVersion) + ", got " +
                  std::to_string(version));
    Scene s;
    s.source = source;
    ContentHash inputs; // the scene's text, then each mesh file's
    inputs.add(text);
    if (auto t = r.optional("title")) s.title = t->string();
    if (auto w = r.optional("world")) read_world(*w, s);
    if (auto rs = r.optional("render")) read_render(*rs, s.render);
    JsonReader bodies = r.field("bodies");
    const std::size_t n = bodies.size();
    s.bodies.resize(n);
    s.looks.resize(n);
    ShapeContext shapes{source, &s.meshes, {}, &inputs};
    for (std::size_t i = 0; i < n; ++i)
        read_body(bodies.at(i), static_cast<int>(i), shapes, s.bodies[i], s.looks[i]);
    r.finish();
    s.content_hash = inputs.value();
    std::vector<std::string> names;
    for (const BodyLook& look : s.looks) names.push_back(look.name);
    resolve_followed_body(s.render.camera, names, source);
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
    return out;
}

Scene load_scene_argument(const std::string& argument) {
    const std::string arg = argument.empty() ? "default" : argument;
    std::error_code ec;
    if (std::filesystem::is_regular_file(arg, ec))
        return load_scene(read_input_file(arg, "scene"), arg);
    const std::string file = arg.ends_with(".json") ? arg : arg + ".json";
    const std::string_view builtin = assets::find(std::filesystem::path(file).filename().string());
    if (!builtin.empty() && arg.find('/') == std::string::npos)
        return load_scene(std::string(builtin), "builtin:" + file);
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
