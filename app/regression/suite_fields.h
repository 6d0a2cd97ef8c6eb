#pragma once
// The suite format's field tables (app/scene/field_table.h): what load_suite() reads and what
// `tumble schema suite` prints. docs/regression-testing.md describes the same fields for people.
#include "app/scene/field_table.h"

#include <string_view>

namespace tumble::app::suite_fields {

const Table& suite();          // the whole file
const Table& image_defaults(); // "image_defaults": what every image check starts from
const Table& compare();        // how closely a drawing must match its golden
const Table& scene_entry();    // one element of "scenes"
const Table& image();          // one image check entry
const Table& state();          // one state check entry
const Table& mask();           // a rectangle of pixels to ignore
const Table& quantities();     // quantity -> absolute tolerance

// A name usable in a check's name and in a golden's file name: kNamePattern, as the schema gives
// it to editors, and is_check_name(), the same test as the loader makes it.
inline constexpr const char* kNamePattern = "^[A-Za-z0-9][A-Za-z0-9_.-]*$";
bool is_check_name(std::string_view name);

} // namespace tumble::app::suite_fields
