#include "app/scene/scene_fields.h"

#include "app/scene/materials.h"
#include "app/scene/scene.h"
#include "physics/integrator.h"

namespace tumble::app::scene_fields {
namespace {

using namespace types;

// "a, b, c" -> {"a", "b", "c"}
std::vector<std::string> split_list(const std::string& list) {
    std::vector<std::string> out;
    for (std::size_t at = 0; at <= list.size();) {
        const std::size_t comma = std::min(list.find(", ", at), list.size());
        out.push_back(list.substr(at, comma - at));
        at = comma + 2;
    }
    return out;
}

Type color() {
    Type rgb = array_of(number_in(0, 1), "a component in [0, 1]");
    rgb.min_items = rgb.max_items = 3;
    return any_of({pattern("^#[0-9a-fA-F]{6}$"), rgb});
}

Type inertia() {
    Type rows = array_of(vec3(), "an inertia tensor row");
    rows.min_items = rows.max_items = 3;
    return any_of({vec3(), rows});
}

Type orientation() {
    return any_of({object(quaternion), object(axis_degrees), object(axis_radians)});
}

const char* kFov = "a vertical field of view in degrees, below 179";

} // namespace

// world.integrator: the registry's names and "auto" (accuracy as a setting, docs/accuracy.md).
std::vector<std::string> integrator_choices() {
    std::vector<std::string> names = split_list(physics::integrator_names());
    names.push_back("auto");
    return names;
}

const Table& tolerance() {
    static const Table t{
        "tolerance",
        "the largest global error a run may make, per body, over its whole duration",
        {{"rotation", positive(), "a positive orientation error in radians"},
         {"position", positive(), "a positive position error in metres"}}};
    return t;
}

const Table& world() {
    static const Table t{
        "world",
        "the physics: gravity, time step, duration, integrator, contact settings",
        {{"gravity", vec3(), "gravity [x, y, z] in m/s^2"},
         {"dt", positive(), "a positive time step in seconds"},
         {"duration", positive(), "a positive duration in seconds"},
         {"integrator", one_of(integrator_choices()),
          "an integrator's name, or \"auto\": the cheapest that meets world.tolerance"},
         {"tolerance", any_of({positive(), object(tolerance)}),
          "a positive error bound (rad and m), or {\"rotation\": rad, \"position\": m}"},
         {"sleeping", boolean(), "true or false: bodies at rest may sleep"},
         {"substeps", integer(0, 64), "contact substeps per step (0: on demand)"},
         {"iterations", integer(0, 64), "contact solve sweeps per substep, 1..64 (0: on demand)"},
         {"contact_tolerance", positive(),
          "a positive length in metres: the largest contact sag effort on demand accepts"},
         {"restitution_threshold", non_negative(), "an impact speed >= 0 in m/s"},
         {"parallel_min_bodies", integer(0, 1 << 30),
          "a body count >= 0 from which --threads is used"},
         {"error_estimate", any_of({boolean(), object(error_estimate)}),
          "true, false or {\"times\": [t1, t2, ...]}: estimate each body's error (step "
          "doubling)"}}};
    return t;
}

const Table& error_estimate() {
    static const Table t{
        "error_estimate",
        "each dynamic body's estimated global error, at the end and at these times",
        {{"times", array_of(non_negative(), "a time >= 0 in seconds, within the duration"),
          "a list of times in seconds at which to report the estimate (besides the end)", true}}};
    return t;
}

const Table& light() {
    static const Table t{
        "light",
        "the key light",
        {{"direction", vec3(), "the direction the light travels [x, y, z]"},
         {"color", color(), "a colour \"#rrggbb\" or [r, g, b] in [0, 1]"},
         {"ambient", non_negative(), "a non-negative ambient fraction"},
         {"angle", number_in(0.0, 20.0), "the light's angular diameter in degrees, 0 to 20"}}};
    return t;
}

const Table& camera_auto() {
    static const Table t{
        "camera_auto",
        "a fixed camera chosen to keep every moving body in view",
        {{"direction", vec3(), "a direction from the target towards the camera"},
         {"margin", non_negative(), "a margin >= 0, a fraction of the half-frame"}}};
    return t;
}

const Table& orbit() {
    static const Table t{"orbit",
                         "the camera circling a centre",
                         {{"center", vec3(), "an orbit centre in metres"},
                          {"radius", positive(), "a positive orbit radius in metres"},
                          {"height", number(), "an orbit height in metres"},
                          {"start_deg", number(), "a start angle in degrees"},
                          {"period", number(), "seconds per turn (negative: clockwise)", true}}};
    return t;
}

const Table& follow() {
    static const Table t{
        "follow",
        "the camera following a body",
        {{"body", any_of({string(), integer(0, 1 << 30)}), "a body's name or index", true},
         {"offset", vec3(), "a camera offset from the body [x, y, z] in metres"},
         {"track", boolean(), "true or false: keep looking at the body"}}};
    return t;
}

const Table& keyframe() {
    static const Table t{"keyframe",
                         "a camera keyframe",
                         {{"t", non_negative(), "a key time in seconds", true},
                          {"position", vec3(), "a camera position in metres", true},
                          {"target", vec3(), "a camera target in metres", true},
                          {"fov_deg", positive_below(179), kFov}}};
    return t;
}

const Table& camera() {
    static const Table t{
        "camera",
        "where the camera is and how it moves",
        {{"position", vec3(), "a camera position in metres"},
         {"target", vec3(), "a camera target in metres"},
         {"up", vec3(), "an up direction"},
         {"fov_deg", positive_below(179), kFov},
         {"auto", any_of({boolean(), object(camera_auto)}),
          "true, false, or {\"direction\", \"margin\"}"},
         {"orbit", object(orbit), "an orbit"},
         {"follow", object(follow), "a body to follow"},
         {"path", array_of(object(keyframe), "a keyframe {\"t\", \"position\", \"target\"}", 2),
          "an array of at least two keyframes {\"t\", \"position\", \"target\"}"}}};
    return t;
}

const Table& render() {
    static const Table t{"render",
                         "how the scene is drawn",
                         {{"width", integer(RenderSettings::kMinSide, RenderSettings::kMaxWidth),
                           "an image width in pixels"},
                          {"height", integer(RenderSettings::kMinSide, RenderSettings::kMaxHeight),
                           "an image height in pixels"},
                          {"fps", integer(1, 1000), "frames per second"},
                          {"camera", object(camera), "a camera"},
                          {"light", object(light), "a light"},
                          {"background", color(), "a colour \"#rrggbb\" or [r, g, b] in [0, 1]"},
                          {"shadows", boolean(), "true or false"},
                          {"antialiasing", boolean(), "true or false"},
                          {"overlay", boolean(), "true or false"},
                          {"axes", boolean(), "true or false"},
                          {"vectors", boolean(), "true or false"},
                          {"soft_shadows", boolean(), "true or false"},
                          {"ambient_occlusion", boolean(), "true or false"},
                          {"reflections", boolean(), "true or false"},
                          {"chart", object(chart), "strip charts {\"quantities\": [...], ...}"},
                          {"trails", any_of({boolean(), object(trails)}),
                           "true, false or {\"seconds\": s, \"axis\": \"x\"}"},
                          {"poinsot", string(), "the name of a body that moves"},
                          {"overlay_body", string(), "the name of a body that moves"}}};
    return t;
}

const Table& chart() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (int i = 0; i < kQuantityCount; ++i)
            out.emplace_back(quantity_info(static_cast<Quantity>(i)).name);
        return out;
    }();
    static const Table t{
        "chart",
        "strip charts in the frame, one panel per quantity",
        {{"quantities", array_of(one_of(names), "a quantity to chart", 1),
          "a list of quantities to chart", true},
         {"body", string(), "the name of the body charted (default: the scene's sums)"},
         {"window", non_negative(), "a window in seconds (0: the whole run)"}}};
    return t;
}

const Table& trails() {
    static const Table t{"trails",
                         "the paths of the moving bodies, fading",
                         {{"seconds", positive(), "a trail length in seconds"},
                          {"axis", one_of({"x", "y", "z"}), "\"x\", \"y\" or \"z\""}}};
    return t;
}

const Table& sphere() {
    static const Table t{"sphere",
                         "a sphere",
                         {{"type", one_of({"sphere"}), "\"sphere\"", true},
                          {"radius", positive(), "a positive radius in metres", true}}};
    return t;
}

const Table& box() {
    static const Table t{"box",
                         "a box",
                         {{"type", one_of({"box"}), "\"box\"", true},
                          {"size", vec3(), "box edge lengths [x, y, z] in metres", true}}};
    return t;
}

const Table& plane() {
    static const Table t{"plane",
                         "an infinite static plane, +z its outward normal",
                         {{"type", one_of({"plane"}), "\"plane\"", true},
                          {"extent", positive(), "a positive drawn size in metres"}}};
    return t;
}

const Table& capsule() {
    static const Table t{
        "capsule",
        "a capsule along the body's z axis",
        {{"type", one_of({"capsule"}), "\"capsule\"", true},
         {"radius", positive(), "a positive capsule radius in metres", true},
         {"length", positive(),
          "a positive length in metres of the capsule's straight part, between the centres of "
          "its end caps (a capsule of length 0 is a sphere: use \"sphere\")",
          true}}};
    return t;
}

const Table& mesh() {
    static const Table t{"mesh",
                         "a closed convex triangle mesh from an OBJ file",
                         {{"type", one_of({"mesh"}), "\"mesh\"", true},
                          {"file", string(), "an OBJ file beside the scene or bundled", true},
                          {"scale", positive(), "a positive scale factor"}}};
    return t;
}

const Table& quaternion() {
    static const Table t{"quaternion",
                         "an orientation as a unit quaternion",
                         {{"quaternion",
                           [] {
                               Type q = array_of(number(), "a finite number");
                               q.min_items = q.max_items = 4;
                               return q;
                           }(),
                           "a unit quaternion [w, x, y, z]", true}}};
    return t;
}

const Table& axis_degrees() {
    static const Table t{"axis_degrees",
                         "an orientation as a rotation about an axis, in degrees",
                         {{"axis", vec3(), "a rotation axis [x, y, z]", true},
                          {"angle_deg", number(), "an angle in degrees", true}}};
    return t;
}

const Table& axis_radians() {
    static const Table t{"axis_radians",
                         "an orientation as a rotation about an axis, in radians",
                         {{"axis", vec3(), "a rotation axis [x, y, z]", true},
                          {"angle_rad", number(), "an angle in radians", true}}};
    return t;
}

const Table& material() {
    static const Table t{
        "material",
        "how a surface looks and touches",
        {{"preset", one_of(split_list(material_preset_names())), "a material preset"},
         {"roughness", number_in(0, 1), "a roughness in [0, 1]"},
         {"specular", number_in(0, 1), "a specular in [0, 1]"},
         {"metallic", number_in(0, 1), "a metallic in [0, 1]"},
         {"friction", non_negative(), "a friction coefficient >= 0"},
         {"restitution", number_in(0, 1), "a restitution in [0, 1] (0: no bounce, 1: elastic)"}}};
    return t;
}

const Table& body() {
    static const Table t{
        "body",
        "a rigid body",
        {{"name", string(), "a name"},
         {"shape",
          any_of({object(sphere), object(box), object(plane), object(capsule), object(mesh)}),
          "a shape {\"type\": \"sphere\" | \"box\" | \"plane\" | \"capsule\" | \"mesh\", ...}",
          true},
         {"static", boolean(), "true or false: never moves"},
         {"mass", positive(), "a positive mass in kilograms"},
         {"density", positive(), "a positive density in kg/m^3"},
         {"inertia", inertia(), "principal moments [I1, I2, I3] or a 3x3 tensor, kg m^2"},
         {"position", vec3(), "a position [x, y, z] in metres"},
         {"normal", vec3(), "a plane normal [x, y, z]"},
         {"orientation", orientation(), "an orientation"},
         {"velocity", vec3(), "a velocity [x, y, z] in m/s"},
         {"angular_velocity", vec3(), "an angular velocity [x, y, z] in rad/s"},
         {"angular_velocity_frame", one_of({"world", "body"}), "\"world\" or \"body\""},
         {"gravity_scale", number(), "a finite gravity scale"},
         {"force", vec3(), "a force [x, y, z] in N"},
         {"torque", vec3(), "a torque [x, y, z] in N m"},
         {"color", color(), "a colour \"#rrggbb\" or [r, g, b] in [0, 1]"},
         {"material", any_of({one_of(split_list(material_preset_names())), object(material)}),
          "a preset name or a material object"}}};
    return t;
}

// A viscous rotary damper between two bodies (physics/damper.h).
const Table& damper() {
    static const Table t{
        "damper",
        "a viscous rotary damper: torque c (w_B - w_A) on A, the opposite on B",
        {{"bodies",
          [] {
              Type two = array_of(string(), "a body's name");
              two.min_items = two.max_items = 2;
              return two;
          }(),
          "the names of the two bodies it couples [A, B]", true},
         {"coefficient", non_negative(), "a damping coefficient >= 0 in N m s", true}}};
    return t;
}

const Table& scene() {
    static const Table t{
        "scene",
        "a Tumble scene (docs/scene-format.md)",
        {{"$schema", string(), "the schema this file follows (for editors; not read)"},
         {"format_version", integer(1, 1), "the scene format version, 1", true},
         {"title", string(), "a title"},
         {"world", object(world), "the physics"},
         {"render", object(render), "how the scene is drawn"},
         {"bodies", array_of(object(body), "a body"), "the bodies", true},
         {"dampers", array_of(object(damper), "a damper {\"bodies\": [A, B], \"coefficient\": c}"),
          "viscous rotary dampers between bodies"}}};
    return t;
}

} // namespace tumble::app::scene_fields
