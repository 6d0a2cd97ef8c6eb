#pragma once
// The "v" and "f" lines of an OBJ file, checked before tinyobjloader reads them: it reads a
// number it cannot parse ("nan", "abc", "1e999", a missing one) as 0 and an index it cannot parse
// as whatever digits it finds, without a word. Every vertex must be 3 finite numbers (4 with a
// weight w, 6 with a colour r g b, as tinyobjloader reads them), and every face at least 3
// vertex indices, each a non-zero integer naming a vertex of the file (negative: counted back
// from the last vertex read so far), optionally with "/vt", "//vn" or "/vt/vn" integer parts.
// A "#" starts a comment to the end of the line.
#include <cstddef>
#include <optional>
#include <string>

namespace tumble::app {

struct ObjLineError {
    std::size_t line; // 1-based
    std::string what;
};

// The first bad "v" or "f" line of `text`, or nothing.
std::optional<ObjLineError> check_obj_lines(const std::string& text);

} // namespace tumble::app
