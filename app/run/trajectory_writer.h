#pragma once
// Writes a run as two CSV files, each under a temporary name until finish():
//   <output>                     one row per (sampled step, body):
//       step,t,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz
//     x: body origin (m, world); q: body orientation (body -> world); v: centre-of-mass velocity
//     (m/s, world); w: angular velocity (rad/s, world). %.17g: doubles round-trip exactly.
//   <stem>.diagnostics.csv       one row per sampled step:
//       step,t,kinetic,potential,energy,px,py,pz,lx,ly,lz
//     energies in J, P in kg m/s, L (world, about the origin) in kg m^2/s.
#include "app/scene/scene.h"
#include "io/atomic_file.h"
#include "physics/model.h"
#include "physics/state.h"

#include <cstdio>
#include <string>

namespace tumble::app {

class TrajectoryWriter {
  public:
    TrajectoryWriter(const std::string& states_path, const Scene& scene);
    ~TrajectoryWriter();
    void write(const physics::Model& model, const physics::State& state);
    void finish(); // closes and renames both files into place
    std::string states_path() const { return states_.final_path().string(); }
    std::string diagnostics_path() const { return diags_.final_path().string(); }

  private:
    const Scene& scene_;
    io::AtomicFile states_, diags_;
    std::FILE* states_file_ = nullptr;
    std::FILE* diags_file_ = nullptr;
};

std::string diagnostics_path_for(const std::string& states_path);

} // namespace tumble::app
