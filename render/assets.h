#pragma once
// Files from assets/shaders and assets/fonts, embedded in the binary at build time
// (cmake/TumbleEmbed.cmake), so rendering needs no files at run time.
#include <string_view>
#include <vector>

namespace tumble::render::assets {
std::string_view find(std::string_view file_name); // empty view if there is no such file
std::vector<std::string_view> names();
} // namespace tumble::render::assets
