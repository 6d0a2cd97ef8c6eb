#pragma once
// Scenes from assets/scenes and meshes from assets/meshes, embedded in the binary at build time
// (cmake/TumbleEmbed.cmake), so `tumble render` works with no scene file anywhere.
#include <string_view>
#include <vector>

namespace tumble::app::assets {
std::string_view find(std::string_view file_name); // "default.json", "top.obj"; empty if absent
std::vector<std::string_view> names();
} // namespace tumble::app::assets
