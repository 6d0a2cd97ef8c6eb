#pragma once
// A body named by the user (a scene field such as camera.follow.body or render.chart.body, or a
// command-line option such as --chart-body): its name, or its index in `bodies` as digits.
#include <string>
#include <vector>

namespace tumble::app {

// The index of the body `name` refers to. Throws SceneError naming `file` and `place` (a JSON
// path or an option) when there is none, listing the first few names: "no body named "x" to
// <purpose> (bodies: ground, book, ...)".
int find_body(const std::vector<std::string>& names, const std::string& name,
              const std::string& file, const std::string& place, const std::string& purpose);

} // namespace tumble::app
