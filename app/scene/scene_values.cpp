#include "app/scene/scene_values.h"

#include "app/scene/scene_fields.h"

#include <cmath>
#include <numbers>

namespace tumble::app {

physics::Vec3 read_vec3(const JsonReader& r, const char* what) {
    const auto a = r.vec3(what);
    return {a[0], a[1], a[2]};
}

physics::Vec3 read_vec3(const FieldValue& v) {
    const auto a = v.vec3();
    return {a[0], a[1], a[2]};
}

glm::vec3 read_glm_vec3(const FieldValue& v) {
    const auto a = v.vec3();
    return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2])};
}

glm::vec3 read_glm_vec3(const JsonReader& r, const char* what) {
    const auto a = r.vec3(what);
    return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2])};
}

glm::vec3 read_color(const JsonReader& r) {
    if (r.value().is_string()) {
        const std::string s = r.string();
        auto hex = [&](std::size_t at) { return std::stoi(s.substr(at, 2), nullptr, 16) / 255.0f; };
        const bool ok = s.size() == 7 && s[0] == '#' &&
                        s.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos;
        if (!ok)
            r.fail("expected a colour \"#rrggbb\" or [r, g, b] in [0, 1], got " +
                   describe_json(r.value()));
        return {hex(1), hex(3), hex(5)};
    }
    const auto c = r.vec3("a colour [r, g, b] with components in [0, 1]");
    for (double x : c)
        if (x < 0.0 || x > 1.0)
            r.fail("expected a colour [r, g, b] with components in [0, 1], got " +
                   describe_json(r.value()));
    return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

physics::Quat read_orientation(JsonReader r) {
    namespace fields = scene_fields;
    if (!r.value().is_object()) // as ObjectReader would say it, before picking a table
        ObjectReader(r, fields::axis_degrees());
    if (r.has("quaternion")) {
        ObjectReader o(r, fields::quaternion());
        const FieldValue q = o.field("quaternion");
        if (!q.value().is_array() || q.value().size() != 4)
            q.fail("expected a unit quaternion [w, x, y, z], got " + describe_json(q.value()));
        double c[4];
        for (std::size_t k = 0; k < 4; ++k) c[k] = q.at(k).number();
        const physics::Quat out(c[0], c[1], c[2], c[3]);
        if (std::abs(out.norm() - 1.0) > 1e-3)
            q.fail("expected a unit quaternion [w, x, y, z], got norm " +
                   std::to_string(out.norm()));
        o.finish();
        return out.normalized();
    }
    const bool degrees = r.has("angle_deg");
    ObjectReader o(r, degrees ? fields::axis_degrees() : fields::axis_radians());
    const FieldValue axis_field = o.field("axis");
    const physics::Vec3 axis = read_vec3(axis_field);
    if (axis.norm() == 0.0) axis_field.fail("expected a non-zero rotation axis");
    const double angle = degrees ? o.field("angle_deg").number() * std::numbers::pi / 180.0
                                 : o.field("angle_rad").number();
    o.finish();
    return physics::Quat(Eigen::AngleAxisd(angle, axis.normalized()));
}

} // namespace tumble::app
