#pragma once
// `tumble sweep`: one scene file per combination of --set values, plus a manifest, for a Slurm
// array job (scripts/slurm/render-sweep.sbatch) or any loop to render (docs/cluster.md). Every
// scene is checked by the scene reader before anything is written, so a bad --set is refused the
// way a bad field of a scene file is: the file, the JSON path, what was expected, a suggestion.
#include "app/cluster/sweep_set.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace tumble::app {

struct SweepScene {
    std::string file;                   // "scene_000.json"
    std::vector<nlohmann::json> values; // one per --set
    nlohmann::json scene;
};

struct Sweep {
    std::string source; // the scene as loaded ("builtin:default.json", "shots/flip.json")
    std::vector<SweepSet> sets;
    std::vector<SweepScene> scenes; // the last --set varies fastest
};

inline constexpr std::size_t kMaxSweepScenes = 10000;

// The scenes of `scene_argument` (a file or a built-in name) with every combination of `sets`.
// Mesh files found next to the original scene are named by absolute path in the new scenes,
// which live in another folder. Throws io::BadInput (or SceneError) naming the --set at fault.
Sweep make_sweep(const std::string& scene_argument, const std::vector<std::string>& sets);

// Writes the scenes and manifest.json into `dir` as a whole: into a temporary folder beside it,
// renamed when complete. Refuses (io::BadInput) a `dir` that exists and is not an empty folder.
void write_sweep(const Sweep& sweep, const std::filesystem::path& dir);

// manifest.json: the source, the --set texts and, per scene, its file and values.
nlohmann::json sweep_manifest(const Sweep& sweep);

} // namespace tumble::app
