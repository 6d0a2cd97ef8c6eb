#include "app/scene/materials.h"

#include <iterator>

namespace tumble::app {
namespace {

struct Preset {
    const char* name;
    render::Material material; // roughness, specular, metallic
};

constexpr Preset kPresets[] = {{"plastic", {0.45f, 0.5f, 0.0f}},
                               {"glossy", {0.15f, 0.8f, 0.0f}},
                               {"matte", {0.9f, 0.1f, 0.0f}},
                               {"rubber", {0.7f, 0.2f, 0.0f}},
                               {"metal", {0.2f, 1.0f, 1.0f}}};

double unit_interval(const JsonReader& r, const char* what) {
    const double v = r.number(what);
    if (v < 0.0 || v > 1.0)
        r.fail(std::string("expected ") + what + ", got " + describe_json(r.value()));
    return v;
}

float unit_knob(const JsonReader& r, const char* what) {
    return static_cast<float>(unit_interval(r, what));
}

} // namespace

std::string material_preset_names() {
    std::string out;
    for (const Preset& p : kPresets) out += (out.empty() ? "" : ", ") + std::string(p.name);
    return out;
}

namespace {

render::Material read_preset(const JsonReader& r) {
    const std::string name = r.string();
    for (const Preset& p : kPresets)
        if (name == p.name) return p.material;
    r.fail("unknown material " + describe_json(r.value()) +
           "; presets: " + material_preset_names() +
           ", or {\"roughness\": r, \"specular\": s, \"metallic\": m, \"friction\": mu, "
           "\"restitution\": e}");
}

} // namespace

render::Material read_material(JsonReader r, physics::ShapeKind kind, physics::Material& contact) {
    if (r.value().is_string()) return read_preset(r);
    render::Material m = default_material(kind);
    if (auto p = r.optional("preset")) m = read_preset(*p);
    if (auto v = r.optional("roughness")) m.roughness = unit_knob(*v, "a roughness in [0, 1]");
    if (auto v = r.optional("specular")) m.specular = unit_knob(*v, "a specular in [0, 1]");
    if (auto v = r.optional("metallic")) m.metallic = unit_knob(*v, "a metallic in [0, 1]");
    if (auto v = r.optional("friction"))
        contact.friction = v->non_negative("a friction coefficient >= 0");
    if (auto v = r.optional("restitution"))
        contact.restitution =
            unit_interval(*v, "a restitution in [0, 1] (0: no bounce, 1: elastic)");
    r.finish();
    return m;
}

render::Material default_material(physics::ShapeKind kind) {
    return kind == physics::ShapeKind::Plane ? kPresets[2].material : kPresets[0].material;
}

} // namespace tumble::app
