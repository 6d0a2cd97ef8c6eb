// `tumble goldens check|update MANIFEST`: visual regression against committed golden images.
//   check   renders every listed frame, compares decoded pixels (exact first, then the
//           anti-aliasing-aware count against the budget), writes <name>.actual.png and
//           <name>.diff.png into the artifacts folder for each failure and prints their paths.
//           Exit 0 all match, 1 some differ, 3 some differ *and* the goldens were made by a
//           different GL renderer/version (a renderer mismatch, not necessarily a bug).
//   update  re-renders and rewrites the goldens on purpose; refuses when this machine's renderer
//           differs from the one recorded in the manifest unless --force. With --add-missing
//           it only adds goldens (first, middle and last frame at 320x180) for built-in scenes
//           that have none, touching no existing image: the one command a new scene needs.
//   --scene NAME limits check or update to that scene's entries.
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/regression/golden_manifest.h"
#include "app/run/render_frames.h"
#include "app/run/still.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "io/bad_input.h"
#include "render/png_io.h"
#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <memory>

namespace tumble::app {
namespace {

struct GoldensCommand {
    std::string action; // "check" or "update"
    std::string manifest;
    std::string artifacts = "golden-artifacts"; // where check writes actual and diff images
    bool force = false;
    bool add_missing = false;        // update: only add goldens for built-in scenes without any
    std::vector<std::string> scenes; // only the entries of these scenes (empty: all)
};

// One renderer per set of options (size, samples, picture switches), created on first use.
class RendererCache {
  public:
    render::Renderer& get(const render::RenderOptions& o) {
        const int switches = (o.shadows ? 1 : 0) | (o.soft_shadows ? 2 : 0) |
                             (o.ambient_occlusion ? 4 : 0) | (o.reflections ? 8 : 0);
        auto& r = cache_[{o.width, o.height, o.samples, switches}];
        if (!r) r = std::make_unique<render::Renderer>(o);
        return *r;
    }
    render::Renderer& any() { return get({16, 16}); }

  private:
    std::map<std::array<int, 4>, std::unique_ptr<render::Renderer>> cache_;
};

render::Image render_entry(const GoldenManifest& m, const GoldenEntry& g, RendererCache& cache) {
    const auto local = m.path.parent_path() / g.scene;
    Scene scene = load_scene_argument(std::filesystem::exists(local) ? local.string() : g.scene);
    scene.render.width = g.width;
    scene.render.height = g.height;
    scene.render.overlay = g.overlay;
    return render_still(scene, g.frame, cache.get(render_options(scene.render)));
}

// Scene name of an entry as `tumble scenes` lists it ("default" for "default.json").
std::string scene_stem(const std::string& scene) {
    return std::filesystem::path(scene).stem().string();
}

bool selected(const GoldensCommand& cmd, const GoldenEntry& g) {
    return cmd.scenes.empty() ||
           std::find(cmd.scenes.begin(), cmd.scenes.end(), scene_stem(g.scene)) != cmd.scenes.end();
}

int check(const GoldenManifest& m, const GoldensCommand& cmd, RendererCache& cache) {
    const std::filesystem::path artifacts = cmd.artifacts;
    const std::string renderer = cache.any().gl_renderer(), version = cache.any().gl_version();
    const bool mismatch = renderer != m.gl_renderer || version != m.gl_version;
    if (mismatch)
        std::printf(
            "note: goldens were made with \"%s\" / \"%s\"; this machine has \"%s\" / \"%s\". "
            "Differences may come from the renderer, not from Tumble.\n",
            m.gl_renderer.c_str(), m.gl_version.c_str(), renderer.c_str(), version.c_str());
    int failures = 0;
    int checked = 0;
    for (const GoldenEntry& g : m.entries) {
        if (!selected(cmd, g)) continue;
        ++checked;
        const render::Image actual = render_entry(m, g, cache);
        const render::Image golden = render::read_png(g.image);
        const render::CompareResult r = render::compare_images(actual, golden, g.compare);
        std::printf("%-6s %s: %s\n", r.matches ? "ok" : "FAIL", g.label().c_str(),
                    r.summary.c_str());
        if (r.matches) continue;
        ++failures;
        std::filesystem::create_directories(artifacts);
        const std::string stem = g.image.stem().string();
        render::write_png(artifacts / (stem + ".actual.png"), actual);
        if (r.same_size) render::write_png(artifacts / (stem + ".diff.png"), r.diff);
        std::printf("       golden: %s\n       actual: %s\n", g.image.c_str(),
                    (artifacts / (stem + ".actual.png")).c_str());
        if (r.same_size)
            std::printf("       diff:   %s\n", (artifacts / (stem + ".diff.png")).c_str());
    }
    std::printf("%d golden image(s), %d failed\n", checked, failures);
    return failures == 0 ? kOk : mismatch ? kGoldensFromOtherRenderer : kRunFailed;
}

// Built-in scenes with no golden in the manifest, with their goldens-to-be.
std::vector<GoldenEntry> missing_entries(const GoldenManifest& m) {
    std::vector<GoldenEntry> out;
    for (const std::string& name : builtin_scene_names()) {
        const bool covered =
            std::any_of(m.entries.begin(), m.entries.end(),
                        [&](const GoldenEntry& g) { return scene_stem(g.scene) == name; });
        if (covered) continue;
        const Scene scene = load_scene_argument(name);
        const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
        for (GoldenEntry& g : new_scene_entries(m, name, tl.frames)) out.push_back(g);
    }
    return out;
}

int update(GoldenManifest m, const GoldensCommand& cmd, RendererCache& cache) {
    const std::string renderer = cache.any().gl_renderer(), version = cache.any().gl_version();
    if ((renderer != m.gl_renderer || version != m.gl_version) && !cmd.force &&
        !m.gl_renderer.empty())
        throw io::BadInput("refusing to update goldens made with \"" + m.gl_renderer + "\" / \"" +
                           m.gl_version + "\" from \"" + renderer + "\" / \"" + version +
                           "\"; pass --force to replace them anyway");
    const std::vector<GoldenEntry> added =
        cmd.add_missing ? missing_entries(m) : std::vector<GoldenEntry>{};
    const std::vector<GoldenEntry>& todo = cmd.add_missing ? added : m.entries;
    for (const GoldenEntry& g : todo) {
        if (!cmd.add_missing && !selected(cmd, g)) continue;
        // Goldens are committed: smallest file (level 9) rather than fastest.
        render::write_png(g.image, render_entry(m, g, cache), {render::PngEncoder::libpng, 9});
        std::printf("wrote %s (%s)\n", g.image.c_str(), g.label().c_str());
    }
    if (cmd.add_missing && added.empty()) std::printf("every built-in scene has goldens\n");
    m.gl_renderer = renderer;
    m.gl_version = version;
    save_golden_manifest(m, added);
    return kOk;
}

int run_goldens(const GoldensCommand& cmd) {
    if (cmd.add_missing && cmd.action != "update")
        throw io::BadInput("--add-missing goes with update");
    const GoldenManifest m = load_golden_manifest(cmd.manifest);
    RendererCache cache;
    return cmd.action == "update" ? update(m, cmd, cache) : check(m, cmd, cache);
}

} // namespace

Subcommand add_goldens_command(CLI::App& app) {
    auto cmd = std::make_shared<GoldensCommand>();
    CLI::App* g =
        app.add_subcommand("goldens", "check or update golden images listed in a manifest");
    g->add_option("action", cmd->action, "check | update")
        ->required()
        ->check(CLI::IsMember({"check", "update"}));
    g->add_option("manifest", cmd->manifest,
                  "golden manifest JSON (e.g. tests/goldens/goldens.json)")
        ->required();
    g->add_option("--artifacts", cmd->artifacts, "folder for actual and diff images of failures");
    g->add_flag("--force", cmd->force,
                "update even when the goldens were made by another GL renderer");
    g->add_flag("--add-missing", cmd->add_missing,
                "update: add goldens (first, middle, last frame) for every built-in scene that "
                "has none, leaving the others untouched");
    g->add_option("--scene", cmd->scenes, "only the goldens of this scene (repeatable)");
    return {[g] { return g->parsed(); }, [cmd] { return run_goldens(*cmd); }};
}

} // namespace tumble::app
