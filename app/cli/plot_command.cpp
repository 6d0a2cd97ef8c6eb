// `tumble plot RUN.csv [RUN2.csv ...] --quantity energy --bodies book -o fig.png`: a figure of
// quantities of `tumble simulate` runs for slides, one series per run (its integrator in the
// legend), body and component, drawn by gnuplot (app/plot/figure.h) as PNG or SVG with its script
// and data beside it. The quantities and where each comes from: app/scene/quantity.h
// (the catalogue) and app/plot/table_values.h.
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/gnuplot/gnuplot.h"
#include "app/plot/figure.h"
#include "app/plot/series.h"
#include "app/scene/content_hash.h"
#include "app/scene/scene.h"
#include "app/scene/scene_check.h"
#include "io/bad_input.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

namespace tumble::app {
namespace {

struct PlotCommand {
    std::vector<std::string> runs;
    std::vector<std::string> quantities, bodies, labels;
    std::string scene; // empty: none
    std::string output, title;
    int width = 900, height = 560;
    bool quiet = false;
};

std::vector<Quantity> find_quantities(const std::vector<std::string>& names) {
    std::vector<Quantity> out;
    for (const std::string& n : names) {
        const std::optional<Quantity> q = parse_quantity(n);
        if (!q)
            throw io::BadInput("--quantity " + n +
                               ": no such quantity; valid quantities: " + quantity_names());
        out.push_back(*q);
    }
    return out;
}

std::string joined(const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : ", ") + p;
    return out;
}

plot::FigureLabels labels_for(const PlotCommand& cmd, const plot::PlotRequest& req) {
    std::vector<std::string> what;
    for (Quantity q : req.quantities)
        what.emplace_back(req.quantities.size() == 1 ? quantity_info(q).description
                                                     : quantity_info(q).name);
    const std::string unit(quantity_info(req.quantities.front()).unit);
    plot::FigureLabels l;
    l.ylabel = joined(what) + (unit == "1" ? "" : ", " + unit);
    l.title = cmd.title.empty()
                  ? joined(what) + " of " + (req.bodies.empty() ? "the scene" : joined(req.bodies))
                  : cmd.title;
    return l;
}

std::vector<std::string> labels_of(const PlotCommand& cmd,
                                   const std::vector<plot::RunFiles>& files) {
    if (cmd.labels.empty()) return plot::run_labels(files);
    if (cmd.labels.size() != files.size())
        throw io::BadInput("--labels: " + std::to_string(cmd.labels.size()) + " labels for " +
                           std::to_string(files.size()) + " runs; give one per run, in order");
    return cmd.labels;
}

bool needs_scene(const plot::PlotRequest& req) {
    return !req.bodies.empty() && std::any_of(req.quantities.begin(), req.quantities.end(),
                                              [](Quantity q) { return plot::needs_scene(q); });
}

// The scene the runs record (tumble simulate writes it on their first line), when it is the same
// scene still: a file edited since would give other masses. None when the runs record none.
std::optional<Scene> scene_the_runs_record(const std::vector<plot::RunFiles>& files) {
    const std::optional<SceneRecord> record = plot::recorded_scene(files);
    if (!record) return std::nullopt;
    const std::string hint = "; name the runs' scene with --scene";
    Scene scene;
    try {
        scene = load_scene_argument(record->source);
    } catch (const io::BadInput& e) {
        throw io::BadInput(files.front().states.string() + " was made from " + record->source +
                           ", which cannot be read now (" + e.what() + ")" + hint);
    }
    if (ContentHash::to_hex(scene.content_hash) != record->content_hash)
        throw io::BadInput(files.front().states.string() + " was made from " + record->source +
                           ", which has changed since (content hash " + record->content_hash +
                           ", now " + ContentHash::to_hex(scene.content_hash) + ")" + hint);
    return scene;
}

int run_plot(const PlotCommand& cmd) {
    if (!gnuplot::is_figure_name(cmd.output))
        throw io::BadInput("-o " + cmd.output + ": expected a figure name ending in .png or .svg");
    plot::PlotRequest req;
    req.quantities = find_quantities(cmd.quantities);
    req.bodies = cmd.bodies;
    const std::vector<plot::RunFiles> files = plot::distinct_runs(cmd.runs);
    std::optional<CheckedStart> start; // the scene's model, from --scene or the runs' record
    std::optional<Scene> scene;
    if (!cmd.scene.empty()) {
        scene = load_scene_argument(cmd.scene);
        req.scene_source = cmd.scene;
    } else if (needs_scene(req)) {
        scene = scene_the_runs_record(files);
        if (scene) req.scene_source = scene->source;
    }
    if (scene) {
        start = build_checked(*scene, scene->world.dt);
        req.model = &start->model;
        for (const BodyLook& look : scene->looks) req.scene_bodies.push_back(look.name);
    }
    plot::check_request(req);   // options first: a mistake costs no reading of the tables
    gnuplot::gnuplot_version(); // a missing gnuplot fails before the reading, naming the package
    const std::vector<std::string> labels = labels_of(cmd, files);
    std::vector<plot::Run> runs;
    for (std::size_t i = 0; i < files.size(); ++i)
        runs.push_back(plot::read_run(files[i], labels[i], plot::reads_states(req),
                                      plot::reads_diagnostics(req)));
    const std::vector<plot::Series> series = plot::make_series(runs, req);
    plot::draw_figure(cmd.output, series, labels_for(cmd, req), cmd.width, cmd.height);
    if (!cmd.quiet)
        std::fprintf(stderr, "tumble: wrote %s (%zu series; data %s, script %s)\n",
                     cmd.output.c_str(), series.size(),
                     plot::data_path(cmd.output).string().c_str(),
                     std::filesystem::path(cmd.output).replace_extension(".gp").string().c_str());
    return kOk;
}

} // namespace

Subcommand add_plot_command(CLI::App& app) {
    auto cmd = std::make_shared<PlotCommand>();
    CLI::App* p = app.add_subcommand(
        "plot", "figure of quantities of `tumble simulate` runs (PNG or SVG, by gnuplot)");
    p->add_option("runs", cmd->runs,
                  "states CSVs written by `tumble simulate -o` (or their .diagnostics.csv); "
                  "the legend names each run's integrator if its file name does")
        ->required();
    p->add_option("--quantity", cmd->quantities,
                  "what to draw, one or several of one unit: " + quantity_names())
        ->required()
        ->delimiter(',');
    p->add_option("--bodies", cmd->bodies,
                  "bodies by name (default: the scene's totals from the diagnostics)")
        ->delimiter(',');
    p->add_option("--scene", cmd->scene,
                  "the runs' scene (file or built-in name): the masses and inertia that a body's "
                  "energy or momentum needs (default: the scene the runs record)");
    p->add_option("--labels", cmd->labels, "legend names of the runs, in order")->delimiter(',');
    p->add_option("--title", cmd->title, "the figure's title");
    p->add_option("-o,--output", cmd->output,
                  "figure: .png or .svg; its gnuplot script (.gp) and data (.dat) go beside it")
        ->required();
    p->add_option("--width", cmd->width, "figure width in pixels (default 900)")
        ->check(CLI::Range(200, 8000));
    p->add_option("--height", cmd->height, "figure height in pixels (default 560)")
        ->check(CLI::Range(150, 8000));
    p->add_flag("-q,--quiet", cmd->quiet, "print nothing on success");
    return {[p] { return p->parsed(); }, [cmd] { return run_plot(*cmd); }};
}

} // namespace tumble::app
