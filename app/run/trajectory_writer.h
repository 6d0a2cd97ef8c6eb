#pragma once
// Writes a run as two CSV files, each under a temporary name until finish():
//   <output>                     the scene it was made from on its first line
//                                (app/run/trajectory_rows.h: kSceneRecordPrefix), then
//                                one row per (sampled step, body):
//       step,t,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz
//     x: body origin (m, world); q: body orientation (body -> world); v: centre-of-mass velocity
//     (m/s, world); w: angular velocity (rad/s, world). %.17g: doubles round-trip exactly.
//   <diagnostics>                one row per sampled step (by default <stem>.diagnostics.csv):
//       step,t,kinetic,potential,energy,px,py,pz,lx,ly,lz
//     energies in J, P in kg m/s, L (world, about the origin) in kg m^2/s.
//     With an error estimate (app/run/run_estimate.h), then per dynamic body i:
//       err_rad_<i>,err_m_<i>   its estimated global error at t: orientation (rad) and centre of
//     mass (m), by step doubling (physics/error_estimate.h); empty once it no longer holds (the
//     body met a contact or fell asleep: the run summary says when).
// An output may be "-" (standard output) or a FIFO: rows then stream out as they are computed
// (io/output_target.h). A run cut short is kept apart from a complete one: finish_interrupted()
// stores it as <stem>.interrupted.csv, so an existing complete file of the same name survives.
#include "app/run/trajectory_rows.h"
#include "app/scene/scene.h"
#include "io/atomic_file.h"
#include "physics/error_estimate.h"
#include "physics/model.h"
#include "physics/state.h"

#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tumble::app {

class TrajectoryWriter {
  public:
    // An empty `diagnostics_path` writes no diagnostics. With `estimate`, the diagnostics rows
    // carry its columns, as it stands when write(model, state) is called (at the state's step).
    TrajectoryWriter(const std::string& states_path, const std::string& diagnostics_path,
                     const Scene& scene, const physics::ErrorEstimator* estimate = nullptr);
    // For rows made earlier with an error estimate (the Python module's Trajectory.write_csv):
    // the diagnostics carry the columns of the bodies of `estimate_columns` (BodyEstimate::body),
    // and write(rows, diagnostics, estimate) gives each row's values.
    TrajectoryWriter(const std::string& states_path, const std::string& diagnostics_path,
                     const Scene& scene, std::span<const physics::BodyEstimate> estimate_columns);
    ~TrajectoryWriter();
    void write(const physics::Model& model, const physics::State& state);
    // Rows made earlier (app/run/trajectory_rows.h), e.g. only some bodies at sampled times.
    void write(const std::vector<StateRow>& rows, const DiagnosticsRow& diagnostics);
    void write(const std::vector<StateRow>& rows, const DiagnosticsRow& diagnostics,
               std::span<const physics::BodyEstimate> estimate);
    // Closes both files and renames them into place; returns the paths written.
    std::vector<std::string> finish();
    // The same for a run that stopped early: into interrupted_path_for(...) names, leaving files
    // of the complete names untouched (streams just end).
    std::vector<std::string> finish_interrupted();

  private:
    TrajectoryWriter(const std::string& states_path, const std::string& diagnostics_path,
                     const Scene& scene, const physics::ErrorEstimator* estimate,
                     const std::string& estimate_header, std::size_t estimate_columns);
    std::vector<std::string> close_and_commit(bool interrupted);
    const Scene& scene_;
    const physics::ErrorEstimator* estimate_;
    std::size_t estimate_columns_; // bodies of an estimate given with the rows (0: none)
    io::AtomicFile states_;
    std::optional<io::AtomicFile> diags_;
    std::string interrupted_diagnostics_; // where finish_interrupted() puts the diagnostics
    std::FILE* states_file_ = nullptr;
    std::FILE* diags_file_ = nullptr;
};

// "out/run.csv" -> "out/run.diagnostics.csv"
std::string diagnostics_path_for(const std::string& states_path);
// "out/run.csv" -> "out/run.interrupted.csv"
std::string interrupted_path_for(const std::string& path);

} // namespace tumble::app
