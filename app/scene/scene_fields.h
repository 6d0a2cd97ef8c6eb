#pragma once
// The scene format's field tables (app/scene/field_table.h): what the loaders read, and what
// `tumble schema scene` prints. docs/scene-format.md describes the same fields for people. Rules
// that span fields or need physics (mass or density, a plane's normal or orientation, at most one
// camera motion, a unit quaternion, a closed mesh, inertia's triangle inequality) stay in the
// loaders' code and are not in the schema.
#include "app/scene/field_table.h"

namespace tumble::app::scene_fields {

const Table& scene(); // the whole file
const Table& world();
const Table& tolerance();                      // world.tolerance as an object
std::vector<std::string> integrator_choices(); // world.integrator: the registry's names + "auto"
const Table& error_estimate();                 // world.error_estimate as an object
const Table& render();
const Table& light();
const Table& chart();  // render.chart
const Table& trails(); // render.trails as an object
const Table& camera();
const Table& camera_auto();
const Table& orbit();
const Table& follow();
const Table& keyframe();
const Table& body();
const Table& damper(); // an element of "dampers"
// Shapes, one table per "type" (the loader picks by type; the schema offers them as anyOf).
const Table& sphere();
const Table& box();
const Table& plane();
const Table& capsule();
const Table& mesh();
// Orientations: a quaternion, or an axis with an angle in degrees or radians.
const Table& quaternion();
const Table& axis_degrees();
const Table& axis_radians();
const Table& material();

} // namespace tumble::app::scene_fields
