#pragma once
// Input files (scenes, OBJ meshes, golden manifests) are read whole into memory before they are
// parsed, so each is checked first: a regular file (not a FIFO, device or directory, which could
// block or never end) of at most kMaxInputFileBytes. The limit bounds what one input can make
// Tumble allocate: a JSON document held in memory takes several times its text (measured for
// a 200,000-body scene: README, "What Tumble promises").
#include <cstdint>
#include <filesystem>
#include <string>

namespace tumble::app {

inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{256} << 20; // 256 MiB

// The whole text of `path`; throws SceneError(path, "file", ...) naming what is wrong with it.
// `what` names the kind of file in messages ("scene", "OBJ mesh", "golden manifest").
std::string read_input_file(const std::filesystem::path& path, const std::string& what);

} // namespace tumble::app
