#include "app/plot/run_files.h"

#include "app/run/trajectory_reader.h"
#include "app/run/trajectory_writer.h"
#include "app/scene/scene_error.h"
#include "io/bad_input.h"
#include "physics/integrator.h"

#include <algorithm>
#include <cctype>

namespace tumble::app::plot {
namespace {

constexpr std::string_view kDiagnosticsSuffix = ".diagnostics.csv";

bool alnum(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

// Whether `name` occurs in `stem` with no letter or digit right before or after it.
bool stands_alone(const std::string& stem, std::string_view name) {
    for (std::size_t at = stem.find(name); at != std::string::npos; at = stem.find(name, at + 1)) {
        const std::size_t end = at + name.size();
        if ((at == 0 || !alnum(stem[at - 1])) && (end == stem.size() || !alnum(stem[end])))
            return true;
    }
    return false;
}

} // namespace

RunFiles run_files(const std::string& argument) {
    if (argument.size() > kDiagnosticsSuffix.size() && argument.ends_with(kDiagnosticsSuffix))
        return {argument.substr(0, argument.size() - kDiagnosticsSuffix.size()) + ".csv", argument};
    return {argument, diagnostics_path_for(argument)};
}

std::vector<RunFiles> distinct_runs(const std::vector<std::string>& arguments) {
    std::vector<RunFiles> out;
    for (const std::string& a : arguments) {
        RunFiles r = run_files(a);
        const bool seen = std::any_of(out.begin(), out.end(),
                                      [&](const RunFiles& o) { return o.states == r.states; });
        if (!seen) out.push_back(std::move(r));
    }
    return out;
}

std::string run_label(const std::filesystem::path& states) {
    const std::string stem = states.stem().string();
    std::string_view best;
    for (const physics::IntegratorInfo& info : physics::integrators()) {
        const std::string_view name = info.name;
        if (name.size() > best.size() && stands_alone(stem, name)) best = name;
    }
    return best.empty() ? stem : std::string(best);
}

std::vector<std::string> run_labels(const std::vector<RunFiles>& runs) {
    std::vector<std::string> labels;
    for (const RunFiles& r : runs) labels.push_back(run_label(r.states));
    std::vector<std::string> out = labels;
    for (std::size_t i = 0; i < runs.size(); ++i)
        for (std::size_t j = 0; j < runs.size(); ++j)
            if (i != j && labels[i] == labels[j]) {
                const std::string stem = runs[i].states.stem().string();
                if (stem != labels[i])
                    out[i] = labels[i] + " (" + stem + ")";
                else
                    out[i] = runs[i].states.string();
            }
    return out;
}

std::optional<SceneRecord> recorded_scene(const std::vector<RunFiles>& runs) {
    std::optional<SceneRecord> first;
    for (const RunFiles& r : runs) {
        const std::optional<SceneRecord> here = read_scene_record(r.states);
        if (&r == &runs.front()) first = here;
        if (!first) return std::nullopt;
        if (!here || here->source != first->source || here->content_hash != first->content_hash)
            throw io::BadInput(r.states.string() + " was not made from the scene of " +
                               runs.front().states.string() + " (" + first->source +
                               "): name the scene with --scene");
    }
    return first;
}

Run read_run(const RunFiles& files, const std::string& label, bool states, bool diagnostics) {
    Run run;
    run.label = label;
    run.files = files;
    if (states) run.states = read_trajectory(files.states).states;
    std::error_code ec;
    if (diagnostics && !std::filesystem::exists(files.diagnostics, ec))
        throw SceneError(files.diagnostics.string(), "file",
                         "no such file: the scene's totals come from the diagnostics that "
                         "`tumble simulate` writes beside " +
                             files.states.string() +
                             " (unless --diagnostics none); or plot a body's with --bodies");
    if (diagnostics) run.diagnostics = read_diagnostics(files.diagnostics);
    return run;
}

} // namespace tumble::app::plot
