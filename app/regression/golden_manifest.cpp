#include "app/regression/golden_manifest.h"

#include "app/scene/input_file.h"
#include "app/scene/json_reader.h"
#include "app/scene/scene.h"
#include "io/atomic_file.h"

#include <cstdio>
#include <fstream>

namespace tumble::app {
namespace {

std::string read_file(const std::filesystem::path& p) {
    return read_input_file(p, "golden manifest");
}

render::CompareOptions read_compare(JsonReader r, render::CompareOptions c) {
    if (auto t = r.optional("tolerance"))
        c.tolerance = t->integer(0, 255, "a per-channel tolerance");
    if (auto p = r.optional("perceptual_threshold")) {
        c.perceptual_threshold = p->non_negative("a YIQ threshold in [0, 1]");
        if (c.perceptual_threshold > 1.0) p->fail("expected a YIQ threshold in [0, 1]");
    }
    if (auto m = r.optional("max_different"))
        c.max_different = m->integer(0, 1 << 30, "a maximum count of differing pixels");
    if (auto a = r.optional("detect_antialiasing")) c.detect_antialiasing = a->boolean();
    r.finish();
    return c;
}

std::string image_name(const std::string& scene, std::int64_t frame, bool overlay) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%04lld", static_cast<long long>(frame));
    return std::filesystem::path(scene).stem().string() + "_" + digits +
           (overlay ? "_overlay" : "") + ".png";
}

} // namespace

std::vector<GoldenEntry> new_scene_entries(const GoldenManifest& m, const std::string& scene,
                                           std::int64_t frames) {
    std::vector<GoldenEntry> out;
    render::CompareOptions defaults;
    const nlohmann::json root = parse_json(read_file(m.path), m.path.string());
    if (root.contains("compare"))
        defaults = read_compare(JsonReader(root["compare"], m.path.string(), "/compare"), defaults);
    for (std::int64_t frame : {std::int64_t{0}, frames / 2, frames - 1}) {
        if (!out.empty() && out.back().frame == frame) continue; // a scene of one or two frames
        GoldenEntry g;
        g.scene = scene;
        g.frame = frame;
        g.compare = defaults;
        g.image = m.path.parent_path() / image_name(scene, frame, false);
        out.push_back(g);
    }
    return out;
}

std::string GoldenEntry::label() const {
    return scene + " frame " + std::to_string(frame) + (overlay ? " with overlay" : "");
}

GoldenManifest load_golden_manifest(const std::filesystem::path& path) {
    const std::string text = read_file(path);
    const nlohmann::json root = parse_json(text, path.string());
    JsonReader r(root, path.string(), "");
    GoldenManifest m;
    m.path = path;
    m.gl_renderer = r.field("gl_renderer").string();
    m.gl_version = r.field("gl_version").string();
    render::CompareOptions defaults;
    if (auto c = r.optional("compare")) defaults = read_compare(*c, defaults);
    JsonReader images = r.field("images");
    for (std::size_t i = 0; i < images.size(); ++i) {
        JsonReader e = images.at(i);
        GoldenEntry g;
        g.scene = e.field("scene").string();
        g.frame = e.field("frame").integer(0, 1 << 30, "a frame index");
        using RS = RenderSettings;
        if (auto w = e.optional("width"))
            g.width = w->integer(RS::kMinSide, RS::kMaxWidth, "an image width");
        if (auto h = e.optional("height"))
            g.height = h->integer(RS::kMinSide, RS::kMaxHeight, "an image height");
        if (auto o = e.optional("overlay")) g.overlay = o->boolean();
        g.compare = defaults;
        if (auto c = e.optional("compare")) g.compare = read_compare(*c, defaults);
        g.image = path.parent_path() / image_name(g.scene, g.frame, g.overlay);
        e.finish();
        m.entries.push_back(g);
    }
    r.finish();
    return m;
}

void save_golden_manifest(const GoldenManifest& m, const std::vector<GoldenEntry>& added) {
    nlohmann::json root = parse_json(read_file(m.path), m.path.string());
    root["gl_renderer"] = m.gl_renderer;
    root["gl_version"] = m.gl_version;
    for (const GoldenEntry& g : added) {
        nlohmann::json e = {
            {"scene", g.scene}, {"frame", g.frame}, {"width", g.width}, {"height", g.height}};
        if (g.overlay) e["overlay"] = true;
        root["images"].push_back(e);
    }
    io::AtomicFile file(m.path);
    std::ofstream out(file.temp_path(), std::ios::binary);
    out << root.dump(2) << "\n";
    out.close();
    if (!out) throw SceneError(m.path.string(), "file", "cannot write the manifest");
    file.commit();
}

} // namespace tumble::app
