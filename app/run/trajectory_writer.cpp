#include "app/run/trajectory_writer.h"

#include "io/bad_input.h"

#include "physics/diagnostics.h"

#include <filesystem>
#include <stdexcept>

namespace tumble::app {
namespace {

// CSV field: quoted, with inner quotes doubled (RFC 4180).
std::string csv_quote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::FILE* open_or_throw(const std::filesystem::path& temp, const std::filesystem::path& final) {
    std::FILE* f = std::fopen(temp.c_str(), "w");
    if (!f) throw std::runtime_error(final.string() + ": cannot create the file");
    return f;
}

} // namespace

std::string diagnostics_path_for(const std::string& states_path) {
    std::filesystem::path p(states_path);
    return (p.parent_path() / (p.stem().string() + ".diagnostics.csv")).string();
}

TrajectoryWriter::TrajectoryWriter(const std::string& states_path, const Scene& scene)
    : scene_(scene), states_(states_path), diags_(diagnostics_path_for(states_path)) {
    try {
        io::ensure_writable_directory(std::filesystem::path(states_path).parent_path());
    } catch (const io::FileError& e) {
        throw io::BadInput(e.what()); // the output named a folder that cannot be used
    }
    states_file_ = open_or_throw(states_.temp_path(), states_.final_path());
    diags_file_ = open_or_throw(diags_.temp_path(), diags_.final_path());
    std::fputs("step,t,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n", states_file_);
    std::fputs("step,t,kinetic,potential,energy,px,py,pz,lx,ly,lz\n", diags_file_);
}

TrajectoryWriter::~TrajectoryWriter() {
    if (states_file_) std::fclose(states_file_);
    if (diags_file_) std::fclose(diags_file_);
}

void TrajectoryWriter::write(const physics::Model& m, const physics::State& s) {
    const double t = s.time(m);
    const long long step = static_cast<long long>(s.step);
    for (int i = 0; i < m.body_count(); ++i) {
        const physics::Pose p = physics::body_pose(m, s, i);
        const physics::Quat& q = p.orientation;
        std::fprintf(states_file_,
                     "%lld,%.17g,%d,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                     "%.17g,%.17g,%.17g\n",
                     step, t, i, csv_quote(scene_.looks[i].name).c_str(), p.position.x(),
                     p.position.y(), p.position.z(), q.w(), q.x(), q.y(), q.z(), s.v[i].x(),
                     s.v[i].y(), s.v[i].z(), s.w[i].x(), s.w[i].y(), s.w[i].z());
    }
    const physics::Diagnostics d = physics::diagnose(m, s);
    const physics::Vec3 &P = d.linear_momentum, &L = d.angular_momentum;
    std::fprintf(diags_file_, "%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                 step, t, d.kinetic(), d.potential, d.energy(), P.x(), P.y(), P.z(), L.x(), L.y(),
                 L.z());
}

void TrajectoryWriter::finish() {
    const bool states_ok = std::fclose(states_file_) == 0;
    const bool diags_ok = std::fclose(diags_file_) == 0;
    const bool ok = states_ok && diags_ok;
    states_file_ = diags_file_ = nullptr;
    if (!ok)
        throw std::runtime_error(states_.final_path().string() + ": write failed (disk full?)");
    states_.commit();
    diags_.commit();
}

} // namespace tumble::app
