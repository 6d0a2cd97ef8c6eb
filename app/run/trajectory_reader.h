#pragma once
// Reads back the two tables `tumble simulate` writes (app/run/trajectory_writer.h): a golden
// trajectory of a regression suite is such a pair of files, whole or with only some bodies and
// times. Throws SceneError (bad input) naming the file, the line:column and what was expected.
#include "app/run/trajectory_rows.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tumble::app {

struct Trajectory {
    std::vector<StateRow> states;            // in file order
    std::vector<DiagnosticsRow> diagnostics; // empty when no diagnostics file was read
};

// `diagnostics` may be empty: then only the states are read.
Trajectory read_trajectory(const std::filesystem::path& states,
                           const std::filesystem::path& diagnostics = {});

// The scene a states table records on its first line (kSceneRecordPrefix), if it does; tables
// written before it was recorded have none. Throws SceneError when the line is not a record.
struct SceneRecord {
    std::string source;       // a built-in "builtin:NAME.json" or a file's absolute path
    std::string content_hash; // 16 hex digits
};
std::optional<SceneRecord> read_scene_record(const std::filesystem::path& states);

// The diagnostics table alone (`tumble plot` of scene totals, whose states it need not read).
std::vector<DiagnosticsRow> read_diagnostics(const std::filesystem::path& diagnostics);

} // namespace tumble::app
