#include "app/materials.h"

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

float unit_interval(JsonReader r, const char* what) {
    const double v = r.number(what);
    if (v < 0.0 || v > 1.0) r.fail(std::string("expected ") + what + ", got " + r.value().dump());
    return static_cast<float>(v);
}

} // namespace

std::string material_preset_names() {
    std::string out;
    for (const Preset& p : kPresets) out += (out.empty() ? "" : ", ") + std::string(p.name);
    return out;
}

render::Material read_material(JsonReader r) {
    if (r.value().is_string()) {
        const std::string name = r.string();
        for (const Preset& p : kPresets)
            if (name == p.name) return p.material;
        r.fail("unknown material \"" + name + "\"; presets: " + material_preset_names() +
               ", or {\"roughness\": r, \"specular\": s, \"metallic\": m} with values in [0, 1]");
    }
    render::Material m = kPresets[0].material;
    if (auto p = r.optional("preset")) m = read_material(*p);
    if (auto v = r.optional("roughness")) m.roughness = unit_interval(*v, "a roughness in [0, 1]");
    if (auto v = r.optional("specular")) m.specular = unit_interval(*v, "a specular in [0, 1]");
    if (auto v = r.optional("metallic")) m.metallic = unit_interval(*v, "a metallic in [0, 1]");
    r.finish();
    return m;
}

render::Material default_material(physics::ShapeKind kind) {
    return kind == physics::ShapeKind::Plane ? kPresets[2].material : kPresets[0].material;
}

} // namespace tumble::app
