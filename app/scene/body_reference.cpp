#include "app/scene/body_reference.h"

#include "app/scene/json_reader.h"
#include "app/scene/scene_error.h"

#include <algorithm>
#include <charconv>

namespace tumble::app {

int find_body(const std::vector<std::string>& names, const std::string& n, const std::string& file,
              const std::string& place, const std::string& purpose) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == n) return int(i);
    // A body index: digits only (from_chars takes no sign, space or "+" for an unsigned), and
    // too many of them is out of range, not an exception (std::stoul threw std::out_of_range).
    std::size_t index = 0;
    const auto [end, ec] = std::from_chars(n.data(), n.data() + n.size(), index);
    if (!n.empty() && ec == std::errc() && end == n.data() + n.size() && index < names.size())
        return int(index);
    // Short whatever the scene: the first few names, a long one as an excerpt (describe_json).
    constexpr std::size_t kListed = 8, kLongName = 60;
    std::string known;
    for (std::size_t i = 0; i < std::min(names.size(), kListed); ++i)
        known +=
            (i ? ", " : "") + (names[i].size() <= kLongName ? names[i] : describe_json(names[i]));
    if (names.size() > kListed) known += ", ... (" + std::to_string(names.size()) + " bodies)";
    throw SceneError(file, place,
                     "no body named " + describe_json(n) + " to " + purpose + " (bodies: " + known +
                         ")");
}

} // namespace tumble::app
