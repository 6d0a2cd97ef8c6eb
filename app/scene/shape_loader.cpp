#include "app/scene/shape_loader.h"

#include "app/scene/obj_lines.h"
#include "app/scene/scene_fields.h"
#include "app/scene/scene_values.h"

namespace tumble::app {
namespace {

using physics::Shape;
using physics::Vec3;

Shape read_box(ObjectReader& r) {
    const FieldValue size = r.field("size");
    const Vec3 full = read_vec3(size);
    if (full.minCoeff() <= 0.0)
        size.fail("expected positive box edge lengths, got " + describe_json(size.value()));
    return Shape::box(0.5 * full);
}

// {"type": "capsule", "radius": r, "length": L}: L is the length of the straight part, the
// distance between the centres of the two end hemispheres (the whole capsule is L + 2 r long),
// along the body's z axis.
Shape read_capsule(ObjectReader& r) {
    const double radius = r.field("radius").number();
    const double length = r.field("length").number();
    return Shape::capsule(radius, 0.5 * length);
}

const std::pair<ObjMesh, std::uint32_t>& load_mesh(JsonReader file, double scale, ShapeContext& c) {
    const std::string name = file.string();
    const auto key = std::make_pair(name, scale);
    if (auto it = c.loaded.find(key); it != c.loaded.end()) return it->second;
    ObjMesh mesh;
    const auto text = find_obj_text(name, c.scene_source, mesh.origin);
    if (!text)
        file.fail("no mesh file " + describe_json(file.value()) +
                  " next to the scene file nor among the bundled meshes (assets/meshes/)");
    if (c.inputs) c.inputs->add(*text);    // Scene::content_hash
    if (auto bad = check_obj_lines(*text)) // app/scene/obj_lines.h
        file.fail(mesh.origin + ":" + std::to_string(bad->line) + ": " + bad->what);
    auto solid = std::make_shared<physics::TriangleMesh>();
    if (auto why = parse_obj(*text, scale, *solid)) file.fail(mesh.origin + ": " + *why);
    if (auto why = physics::check_closed_mesh(*solid))
        file.fail(mesh.origin + ": expected a closed, outward-wound triangle mesh: " + *why);
    mesh.drawn = drawn_mesh(*solid);
    mesh.solid = std::move(solid);
    const auto id = static_cast<std::uint32_t>(c.drawn->size());
    c.drawn->push_back(mesh.drawn);
    return c.loaded.emplace(key, std::make_pair(std::move(mesh), id)).first->second;
}

} // namespace

// The table of the shape's type, or SceneError naming the types.
static const Table& shape_table(JsonReader& r) {
    namespace fields = scene_fields;
    const std::string type = r.field("type").string();
    for (const Table* t :
         {&fields::sphere(), &fields::box(), &fields::plane(), &fields::capsule(), &fields::mesh()})
        if (t->id == type) return *t;
    const JsonReader t = r.field("type");
    t.fail("unknown shape " + describe_json(t.value()) +
           "; expected one of: sphere, box, plane, capsule, mesh");
}

void read_shape(JsonReader json, ShapeContext& c, physics::BodyDef& b, BodyLook& look) {
    ObjectReader r(json, shape_table(json));
    const std::string& type = r.table().id;
    if (type == "sphere") {
        b.shape = Shape::sphere(r.field("radius").number());
    } else if (type == "box") {
        b.shape = read_box(r);
    } else if (type == "plane") {
        b.shape = Shape::plane();
        if (auto e = r.optional("extent")) look.plane_extent = static_cast<float>(e->number());
    } else if (type == "capsule") {
        b.shape = read_capsule(r);
    } else {
        const double scale = r.has("scale") ? r.field("scale").number() : 1.0;
        const auto& [mesh, id] = load_mesh(r.field("file").reader(), scale, c);
        b.shape = Shape::mesh();
        b.mesh = mesh.solid;
        look.mesh_id = id;
    }
    r.finish();
}

double body_volume(const physics::BodyDef& b) {
    if (b.shape.kind == physics::ShapeKind::Mesh && b.mesh)
        return physics::mesh_mass_properties(*b.mesh).volume;
    return physics::shape_volume(b.shape);
}

} // namespace tumble::app
