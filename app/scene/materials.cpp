#include "app/scene/materials.h"

#include "app/scene/scene_fields.h"

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

render::Material read_material(JsonReader json, physics::ShapeKind kind,
                               physics::Material& contact) {
    if (json.value().is_string()) return read_preset(json);
    ObjectReader r(json, scene_fields::material());
    render::Material m = default_material(kind);
    if (auto p = r.optional("preset")) m = read_preset(p->reader());
    if (auto v = r.optional("roughness")) m.roughness = static_cast<float>(v->number());
    if (auto v = r.optional("specular")) m.specular = static_cast<float>(v->number());
    if (auto v = r.optional("metallic")) m.metallic = static_cast<float>(v->number());
    if (auto v = r.optional("friction")) contact.friction = v->number();
    if (auto v = r.optional("restitution")) contact.restitution = v->number();
    r.finish();
    return m;
}

render::Material default_material(physics::ShapeKind kind) {
    return kind == physics::ShapeKind::Plane ? kPresets[2].material : kPresets[0].material;
}

} // namespace tumble::app
