#include "app/scene/body_loader.h"

#include "app/scene/materials.h"
#include "app/scene/scene_fields.h"
#include "app/scene/scene_values.h"
#include "app/scene/shape_loader.h"

namespace tumble::app {
namespace {

using physics::Mat3;
using physics::Vec3;

// A pleasant default palette (sRGB), cycled by body index when a body has no "color".
const glm::vec3 kPalette[] = {{0.90f, 0.35f, 0.25f}, {0.25f, 0.55f, 0.85f}, {0.95f, 0.75f, 0.20f},
                              {0.35f, 0.75f, 0.45f}, {0.65f, 0.40f, 0.80f}, {0.95f, 0.55f, 0.70f}};

// A plane without a "color": a light neutral grey, so that a red or blue body stands out on it.
constexpr glm::vec3 kGround{0.78f, 0.78f, 0.76f};

// Inertia about the centre of mass in body axes: [I1, I2, I3] (principal along the body axes)
// or a symmetric 3x3 [[Ixx, Ixy, Ixz], [Iyx, Iyy, Iyz], [Izx, Izy, Izz]], kg m^2.
Mat3 read_inertia(const JsonReader& r) {
    if (r.value().is_array() && r.value().size() == 3 && r.value()[0].is_array()) {
        Mat3 m;
        for (std::size_t i = 0; i < 3; ++i) {
            const Vec3 row = read_vec3(r.at(i), "an inertia tensor row");
            m.row(static_cast<int>(i)) = row.transpose();
        }
        return m;
    }
    return Mat3(read_vec3(r, "principal moments [I1, I2, I3] in kg m^2").asDiagonal());
}

void read_mass(ObjectReader& r, physics::BodyDef& b) {
    auto mass = r.optional("mass");
    auto density = r.optional("density");
    if (mass && density) density->fail("give either \"mass\" or \"density\", not both");
    const double volume = body_volume(b);
    if (mass)
        b.mass = mass->number();
    else
        b.mass = (density ? density->number() : 1000.0) * volume;
}

// A plane's orientation may be given as its normal: the rotation taking +z to `normal`.
physics::Quat plane_orientation(const FieldValue& r) {
    const Vec3 n = read_vec3(r);
    if (n.norm() == 0.0) r.fail("expected a non-zero plane normal");
    return physics::Quat::FromTwoVectors(Vec3::UnitZ(), n.normalized());
}

} // namespace

void read_body(JsonReader json, int index, ShapeContext& shapes, physics::BodyDef& b,
               BodyLook& look) {
    ObjectReader r(json, scene_fields::body());
    look.name = r.has("name") ? r.field("name").string() : "body " + std::to_string(index);
    look.color = kPalette[index % std::size(kPalette)];
    read_shape(r.field("shape").reader(), shapes, b, look); // app/scene/shape_loader.h
    const bool plane = b.shape.kind == physics::ShapeKind::Plane;
    if (plane) look.color = kGround; // a floor, not a body: neutral, so every colour shows on it
    b.motion = plane ? physics::Motion::Static : physics::Motion::Dynamic;
    if (auto s = r.optional("static")) {
        const bool is_static = s->boolean();
        if (plane && !is_static) s->fail("a plane is infinite and is always static");
        b.motion = is_static ? physics::Motion::Static : physics::Motion::Dynamic;
    }
    read_mass(r, b);
    if (auto i = r.optional("inertia")) {
        b.inertia = read_inertia(i->reader());
        if (b.inertia.isZero(0.0)) i->fail("expected positive moments of inertia, got all zeros");
    }
    if (auto p = r.optional("position")) b.position = read_vec3(*p);
    auto normal = r.optional("normal");
    if (normal && !plane)
        normal->fail("\"normal\" places a plane; give this body an \"orientation\"");
    if (auto o = r.optional("orientation")) {
        if (normal) o->fail("give either \"orientation\" or \"normal\" for a plane, not both");
        b.orientation = read_orientation(o->reader());
    } else if (normal) {
        b.orientation = plane_orientation(*normal);
    }
    if (auto v = r.optional("velocity")) b.velocity = read_vec3(*v);
    if (auto w = r.optional("angular_velocity")) b.angular_velocity = read_vec3(*w);
    if (auto f = r.optional("angular_velocity_frame")) {
        const std::string frame = f->string();
        if (frame == "body")
            b.angular_velocity = b.orientation.normalized() * b.angular_velocity;
        else if (frame != "world")
            f->fail("expected \"world\" or \"body\", got " + describe_json(f->value()));
    }
    if (auto g = r.optional("gravity_scale")) b.gravity_scale = g->number();
    if (auto f = r.optional("force")) b.applied_force = read_vec3(*f);
    if (auto t = r.optional("torque")) b.applied_torque = read_vec3(*t);
    if (auto c = r.optional("color")) look.color = read_color(c->reader());
    if (auto m = r.optional("material")) // look, friction, restitution (app/scene/materials.h)
        look.material = read_material(m->reader(), b.shape.kind, b.material);
    r.finish();
}

} // namespace tumble::app
