#pragma once
// One row of each trajectory table (app/run/trajectory_writer.h has the columns and units): what
// `tumble simulate` writes, what a regression suite's golden trajectory holds, and what its state
// checks compare. Made from a state here, printed by the writer, parsed back by the reader
// (app/run/trajectory_reader.h), so the three agree by construction.
#include "physics/math.h"
#include "physics/model.h"
#include "physics/state.h"

#include <cstdint>
#include <cstdio>
#include <string>

namespace tumble::app {

struct StateRow {
    std::int64_t step = 0;
    double t = 0.0;
    int body = 0;
    std::string name;
    physics::Vec3 x = physics::Vec3::Zero(); // body origin, world, m
    physics::Quat q = physics::Quat::Identity();
    physics::Vec3 v = physics::Vec3::Zero(); // centre-of-mass velocity, world, m/s
    physics::Vec3 w = physics::Vec3::Zero(); // angular velocity, world, rad/s
};

struct DiagnosticsRow {
    std::int64_t step = 0;
    double t = 0.0;
    double kinetic = 0.0, potential = 0.0, energy = 0.0; // J
    physics::Vec3 p = physics::Vec3::Zero();             // linear momentum, kg m/s
    physics::Vec3 l = physics::Vec3::Zero(); // angular momentum about the origin, kg m^2/s
};

StateRow state_row(const physics::Model& model, const physics::State& state, int body,
                   const std::string& name);
DiagnosticsRow diagnostics_row(const physics::Model& model, const physics::State& state);

// The first line of a states table: the scene it was made from, as a comment that gnuplot and
// numpy skip (pandas: read_csv(file, comment='#')), so that `tumble plot` finds the masses a
// body's energy needs without --scene:
//   # tumble scene {"content_hash":"9f0c...","source":"builtin:lessons/intermediate_axis.json"}
// "source" is a built-in scene's name or a scene file's absolute path; "content_hash" the scene's
// (app/scene/content_hash.h, 16 hex digits), to tell whether the file has changed since.
inline constexpr const char* kSceneRecordPrefix = "# tumble scene ";

inline constexpr const char* kStatesHeader = "step,t,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz";
inline constexpr const char* kDiagnosticsHeader =
    "step,t,kinetic,potential,energy,px,py,pz,lx,ly,lz";

// One CSV line each (%.17g: doubles round-trip exactly; the name quoted as RFC 4180 says).
void print_row(std::FILE* out, const StateRow& row);
void print_row(std::FILE* out, const DiagnosticsRow& row);
// The diagnostics row's fields without the end of line (more columns may follow).
void print_fields(std::FILE* out, const DiagnosticsRow& row);

} // namespace tumble::app
