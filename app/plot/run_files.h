#pragma once
// One `tumble simulate` run as `tumble plot` finds it: its two tables (app/run/trajectory_writer.h)
// and the name its series carry in a legend.
#include "app/run/trajectory_reader.h"
#include "app/run/trajectory_rows.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tumble::app::plot {

struct RunFiles {
    std::filesystem::path states;      // "runs/euler.csv"
    std::filesystem::path diagnostics; // "runs/euler.diagnostics.csv"
};

// A run named by either table: "runs/euler.csv" or "runs/euler.diagnostics.csv" gives both.
RunFiles run_files(const std::string& argument);

// The runs the arguments name, each once and in the order first named: a glob such as
// runs/*.csv names both tables of each run.
std::vector<RunFiles> distinct_runs(const std::vector<std::string>& arguments);

// The integrator a run's file name names ("book_symplectic_euler.csv" -> "symplectic_euler": the
// longest integrator name standing alone in the stem), else the stem: a run's tables do not say
// which integrator made them, so name runs after it (`simulate --integrator euler -o euler.csv`).
std::string run_label(const std::filesystem::path& states);

// Labels for several runs: run_label() of each, made unique by the stem where two would agree.
std::vector<std::string> run_labels(const std::vector<RunFiles>& runs);

struct Run {
    std::string label;
    RunFiles files;
    std::vector<StateRow> states;            // empty unless read
    std::vector<DiagnosticsRow> diagnostics; // empty unless read
};

// The scene the runs' states tables record on their first line (app/run/trajectory_rows.h), for
// a figure that needs masses when --scene is not given: none when the first run records none.
// Throws io::BadInput when two runs record different scenes.
std::optional<SceneRecord> recorded_scene(const std::vector<RunFiles>& runs);

// Reads the tables asked for; throws SceneError (exit 2) naming the file and line:column.
Run read_run(const RunFiles& files, const std::string& label, bool states, bool diagnostics);

} // namespace tumble::app::plot
