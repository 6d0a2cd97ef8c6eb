#include "app/regression/golden_update.h"

#include "app/regression/golden_renderers.h"
#include "app/run/trajectory_writer.h"
#include "app/scene/content_hash.h"
#include "io/atomic_file.h"
#include "io/bad_input.h"
#include "render/png_io.h"

namespace tumble::app {
namespace {

void refuse_other_renderers(const SuiteRun& run, bool force) {
    std::string names;
    GlIdentity theirs;
    for (const CheckResult& r : run.results) {
        if (r.passed || !r.image || !r.golden_from_other_gl) continue;
        names += (names.empty() ? "" : ", ") + r.name();
        theirs = r.image_outcome.golden_gl;
    }
    if (names.empty() || force) return;
    throw io::BadInput("refusing to replace goldens drawn by " + theirs.describe() +
                       " from this machine's " + run.gl.describe() + ": " + names +
                       "; pass --force to replace them anyway (nothing was written)");
}

void write_states(const CheckResult& r) {
    const StateCheck& check = *r.state;
    TrajectoryWriter out(check.golden.string(), check.golden_diagnostics().string(),
                         r.scene->scene);
    for (const Sample& s : r.state_outcome.samples) out.write(s.bodies, s.diagnostics);
    out.finish();
}

std::string line(const CheckResult& r, const std::filesystem::path& file) {
    return (r.golden_missing ? "added   " : "updated ") + file.string() +
           (r.golden_missing ? "" : " (was: " + r.summary + ")");
}

} // namespace

UpdateResult update_goldens(const Suite& suite, const SuiteRun& run, bool force) {
    refuse_other_renderers(run, force);
    UpdateResult out;
    GoldenRenderers record = GoldenRenderers::load(suite.goldens);
    bool images = false;
    for (const CheckResult& r : run.results) {
        if (r.passed) {
            ++out.unchanged;
            continue;
        }
        if (r.run_failed) {
            ++out.impossible;
            out.lines.push_back("cannot update " + r.name() + ": " + r.summary);
            continue;
        }
        io::ensure_writable_directory(suite.goldens);
        if (r.image) {
            // Goldens are committed: the smallest file (zlib level 9) rather than the fastest.
            render::write_png(r.image->golden, r.image_outcome.actual,
                              {render::PngEncoder::libpng, 9});
            record.set(r.image->golden.filename().string(), run.gl,
                       ContentHash::to_hex(r.scene->scene.content_hash));
            images = true;
            out.lines.push_back(line(r, r.image->golden));
        } else {
            write_states(r);
            out.lines.push_back(line(r, r.state->golden) + " and " +
                                r.state->golden_diagnostics().filename().string());
        }
        ++out.written;
    }
    if (images) record.save();
    return out;
}

} // namespace tumble::app
