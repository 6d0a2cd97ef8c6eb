#pragma once
// How deep a JSON text may nest. Arrays and objects inside each other deeper than kMaxJsonDepth
// are refused before anything builds or walks a tree of them: a scene needs about 8 levels, while
// a value nested 100,000 deep would overflow the stack of any recursive walk (printing it, copying
// it, comparing it).
#include <string>

namespace tumble::app {

inline constexpr int kMaxJsonDepth = 256;

// Throws SceneError at the line:column of the first '[' or '{' that opens level
// kMaxJsonDepth + 1 of `text` (the contents of `file`). Brackets inside strings do not count;
// the text need not be valid JSON (the parser judges that afterwards).
void check_json_nesting(const std::string& text, const std::string& file);

} // namespace tumble::app
