#pragma once
// Readers for the value types that recur in scene files (vectors, colours, orientations), shared
// by the world, body and render sections of the loader.
#include "app/scene/field_table.h"
#include "app/scene/json_reader.h"
#include "physics/math.h"

#include <glm/glm.hpp>

namespace tumble::app {

physics::Vec3 read_vec3(const JsonReader& r, const char* what);
glm::vec3 read_glm_vec3(const JsonReader& r, const char* what);
// The same for a field read through its table (app/scene/field_table.h): its words.
physics::Vec3 read_vec3(const FieldValue& v);
glm::vec3 read_glm_vec3(const FieldValue& v);

// [r, g, b] with components in [0, 1], or "#rrggbb". sRGB.
glm::vec3 read_color(const JsonReader& r);

// {"quaternion": [w, x, y, z]} (unit, within 1e-3) or {"axis": [x, y, z], "angle_deg": a}
// or {"axis": [...], "angle_rad": a}.
physics::Quat read_orientation(JsonReader r);

} // namespace tumble::app
