#include "app/run/trajectory_writer.h"

#include "app/scene/content_hash.h"
#include "io/bad_input.h"

#include <nlohmann/json.hpp>

#include "app/run/run_estimate.h"
#include "app/run/trajectory_rows.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace tumble::app {
namespace {

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

// {"source": ..., "content_hash": ...} on one line (kSceneRecordPrefix).
std::string scene_record(const Scene& scene) {
    std::string source = scene.source;
    if (!source.starts_with("builtin:") && !source.empty())
        source = std::filesystem::absolute(source).lexically_normal().string();
    const nlohmann::json record = {{"source", source},
                                   {"content_hash", ContentHash::to_hex(scene.content_hash)}};
    return record.dump();
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
                                   const std::string& diagnostics_path, const Scene& scene,
                                   const physics::ErrorEstimator* estimate)
    : TrajectoryWriter(states_path, diagnostics_path, scene, estimate,
                       estimate ? estimate_csv_header(*estimate) : "", 0) {}

TrajectoryWriter::TrajectoryWriter(const std::string& states_path,
                                   const std::string& diagnostics_path, const Scene& scene,
                                   std::span<const physics::BodyEstimate> estimate_columns)
    : TrajectoryWriter(states_path, diagnostics_path, scene, nullptr,
                       estimate_csv_header(estimate_columns), estimate_columns.size()) {}

TrajectoryWriter::TrajectoryWriter(const std::string& states_path,
                                   const std::string& diagnostics_path, const Scene& scene,
                                   const physics::ErrorEstimator* estimate,
                                   const std::string& estimate_header, std::size_t estimate_columns)
    : scene_(scene), estimate_(estimate), estimate_columns_(estimate_columns),
      states_(states_path) {
    if (!diagnostics_path.empty()) diags_.emplace(diagnostics_path);
    // A run cut short: "s.interrupted.csv" and, beside it, "s.interrupted.diagnostics.csv"
    // (or "d.interrupted.csv" for diagnostics the user named d.csv).
    interrupted_diagnostics_ = diagnostics_path == diagnostics_path_for(states_path)
                                   ? diagnostics_path_for(interrupted_path_for(states_path))
                                   : interrupted_path_for(diagnostics_path);
    states_file_ = open_or_throw(states_);
    std::fprintf(states_file_, "%s%s\n%s\n", kSceneRecordPrefix, scene_record(scene).c_str(),
                 kStatesHeader);
    if (diags_) {
        diags_file_ = open_or_throw(*diags_);
        std::fprintf(diags_file_, "%s%s\n", kDiagnosticsHeader, estimate_header.c_str());
    }
}

TrajectoryWriter::~TrajectoryWriter() {
    if (states_file_) std::fclose(states_file_);
    if (diags_file_) std::fclose(diags_file_);
}

void TrajectoryWriter::write(const physics::Model& m, const physics::State& s) {
    for (int i = 0; i < m.body_count(); ++i)
        print_row(states_file_, state_row(m, s, i, scene_.looks[i].name));
    if (!diags_file_) return;
    if (!estimate_) {
        print_row(diags_file_, diagnostics_row(m, s));
        return;
    }
    if (estimate_->main_step() != s.step)
        throw std::logic_error("the error estimate is at step " +
                               std::to_string(estimate_->main_step()) + ", the row at step " +
                               std::to_string(s.step));
    print_fields(diags_file_, diagnostics_row(m, s));
    print_estimate_csv(diags_file_, *estimate_);
    std::fputc('\n', diags_file_);
}

void TrajectoryWriter::write(const std::vector<StateRow>& rows, const DiagnosticsRow& diagnostics) {
    write(rows, diagnostics, {});
}

void TrajectoryWriter::write(const std::vector<StateRow>& rows, const DiagnosticsRow& diagnostics,
                             std::span<const physics::BodyEstimate> estimate) {
    if (estimate_) throw std::logic_error("rows made earlier carry no live error estimate");
    if (estimate.size() != estimate_columns_)
        throw std::logic_error("an estimate of " + std::to_string(estimate.size()) +
                               " bodies for " + std::to_string(estimate_columns_) + " columns");
    for (const StateRow& r : rows) print_row(states_file_, r);
    if (!diags_file_) return;
    print_fields(diags_file_, diagnostics);
    print_estimate_csv(diags_file_, estimate);
    std::fputc('\n', diags_file_);
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
