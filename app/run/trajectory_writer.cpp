#include "app/run/trajectory_writer.h"

#include "io/bad_input.h"

#include "physics/diagnostics.h"

#include <cerrno>
#include <cstring>
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

std::FILE* open_or_throw(const io::AtomicFile& file) {
    if (!file.streaming()) {
        try {
            io::ensure_writable_directory(file.final_path().parent_path());
        } catch (const io::FileError& e) {
            throw io::BadInput(e.what()); // the output named a folder that cannot be used
        }
    }
    std::FILE* f = std::fopen(file.temp_path().c_str(), file.fopen_mode());
    if (!f) {
        throw std::runtime_error("cannot write '" + file.final_path().string() +
                                 "': " + std::strerror(errno));
    }
    return f;
}

} // namespace

std::string diagnostics_path_for(const std::string& states_path) {
    std::filesystem::path p(states_path);
    return (p.parent_path() / (p.stem().string() + ".diagnostics.csv")).string();
}

std::string interrupted_path_for(const std::string& path) {
    std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + ".interrupted" + p.extension().string()))
        .string();
}

TrajectoryWriter::TrajectoryWriter(const std::string& states_path,
                                   const std::string& diagnostics_path, const Scene& scene)
    : scene_(scene), states_(states_path) {
    if (!diagnostics_path.empty()) diags_.emplace(diagnostics_path);
    // A run cut short: "s.interrupted.csv" and, beside it, "s.interrupted.diagnostics.csv"
    // (or "d.interrupted.csv" for diagnostics the user named d.csv).
    interrupted_diagnostics_ = diagnostics_path == diagnostics_path_for(states_path)
                                   ? diagnostics_path_for(interrupted_path_for(states_path))
                                   : interrupted_path_for(diagnostics_path);
    states_file_ = open_or_throw(states_);
    std::fputs("step,t,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n", states_file_);
    if (diags_) {
        diags_file_ = open_or_throw(*diags_);
        std::fputs("step,t,kinetic,potential,energy,px,py,pz,lx,ly,lz\n", diags_file_);
    }
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
    if (!diags_file_) return;
    const physics::Diagnostics d = physics::diagnose(m, s);
    const physics::Vec3 &P = d.linear_momentum, &L = d.angular_momentum;
    std::fprintf(diags_file_, "%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                 step, t, d.kinetic(), d.potential, d.energy(), P.x(), P.y(), P.z(), L.x(), L.y(),
                 L.z());
}

std::vector<std::string> TrajectoryWriter::close_and_commit(bool interrupted) {
    // fclose flushes what is buffered: a full disk shows here (errno ENOSPC, or EFBIG past a
    // file-size limit), or already in the stream's error flag from an earlier write.
    int error = 0;
    auto close = [&error](std::FILE* f) {
        if (!f) return true;
        const bool ok = !std::ferror(f);
        const bool closed = std::fclose(f) == 0;
        if (!closed && error == 0) error = errno;
        return ok && closed;
    };
    const bool states_ok = close(states_file_);
    const bool diags_ok = close(diags_file_);
    states_file_ = diags_file_ = nullptr;
    if (!states_ok || !diags_ok) {
        const io::AtomicFile& failed = states_ok ? *diags_ : states_;
        throw std::runtime_error("cannot write '" + failed.final_path().string() +
                                 "': " + (error ? std::strerror(error) : "write failed"));
    }
    std::vector<std::string> written;
    for (io::AtomicFile* file : {&states_, diags_ ? &*diags_ : nullptr}) {
        if (!file) continue;
        std::string name = file->final_path().string();
        if (interrupted && !file->streaming()) {
            name = file == &states_ ? interrupted_path_for(name) : interrupted_diagnostics_;
            file->commit_as(name);
        } else {
            file->commit();
        }
        written.push_back(file->standard_output() ? "standard output" : name);
    }
    return written;
}

std::vector<std::string> TrajectoryWriter::finish() {
    return close_and_commit(false);
}

std::vector<std::string> TrajectoryWriter::finish_interrupted() {
    return close_and_commit(true);
}

} // namespace tumble::app
