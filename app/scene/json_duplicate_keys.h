#pragma once
// Keys that appear twice in one JSON object. The JSON parser keeps the last of them silently
// (`"mass": -5, "mass": 1` would read as 1), and reports no places of keys, so a scanner over the
// text finds them: it follows the nesting of objects and arrays, reads each key (escapes decoded,
// so "m\u0061ss" is "mass") and remembers where it first appeared.
#include <string>

namespace tumble::app {

// Throws SceneError at the JSON path of the first key that repeats one earlier in the same
// object of `text` (the contents of `file`), naming both places as line:column: "/bodies/0/mass:
// duplicate key "mass": first at 5:7, again at 5:20". `text` must be valid JSON (run it after the
// parser, which also bounds its nesting); the same key in different objects is fine.
void check_duplicate_keys(const std::string& text, const std::string& file);

} // namespace tumble::app
