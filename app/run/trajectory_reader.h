#pragma once
// Reads back the two tables `tumble simulate` writes (app/run/trajectory_writer.h): a golden
// trajectory of a regression suite is such a pair of files, whole or with only some bodies and
// times. Throws SceneError (bad input) naming the file, the line:column and what was expected.
#include "app/run/trajectory_rows.h"

#include <filesystem>
#include <vector>

namespace tumble::app {

struct Trajectory {
    std::vector<StateRow> states;            // in file order
    std::vector<DiagnosticsRow> diagnostics; // empty when no diagnostics file was read
};

// `diagnostics` may be empty: then only the states are read.
Trajectory read_trajectory(const std::filesystem::path& states,
                           const std::filesystem::path& diagnostics = {});

// The diagnostics table alone (`tumble plot` of scene totals, whose states it need not read).
std::vector<DiagnosticsRow> read_diagnostics(const std::filesystem::path& diagnostics);

} // namespace tumble::app
