#include "app/cluster/sweep.h"

#include "app/scene/assets.h"
#include "app/scene/input_file.h"
#include "app/scene/scene.h"
#include "io/atomic_file.h"
#include "io/bad_input.h"
#include "io/interrupt.h"

#include <cstdio>
#include <fstream>

namespace tumble::app {

namespace fs = std::filesystem;

namespace {

// The JSON text of the scene a command names, as load_scene_argument() resolves it.
nlohmann::json scene_json(const std::string& argument, std::string& source) {
    source = load_scene_argument(argument).source; // resolves and checks it
    const std::string text = source.starts_with("builtin:")
                                 ? std::string(assets::find(std::string_view(source).substr(8)))
                                 : read_input_file(source, "scene");
    return nlohmann::json::parse(text);
}

// Mesh files next to the original scene, named by absolute path (the new scene is elsewhere).
void anchor_meshes(nlohmann::json& scene, const std::string& source) {
    if (source.starts_with("builtin:") || !scene.contains("bodies") || !scene["bodies"].is_array())
        return;
    for (nlohmann::json& body : scene["bodies"]) {
        if (!body.is_object() || !body.contains("shape") || !body["shape"].is_object()) continue;
        nlohmann::json& shape = body["shape"];
        if (!shape.contains("file") || !shape["file"].is_string()) continue;
        const fs::path beside = fs::path(source).parent_path() / shape["file"].get<std::string>();
        std::error_code ec;
        if (fs::exists(beside, ec))
            shape["file"] = fs::absolute(beside).lexically_normal().string();
    }
}

// Loads `scene` as the scene reader would; its errors are prefixed with `what`.
void check_scene(const nlohmann::json& scene, const std::string& source, const std::string& what) {
    try {
        (void)load_scene(scene.dump(), source);
    } catch (const io::BadInput& e) {
        throw io::BadInput(what + ": " + e.what());
    }
}

std::string describe_values(const Sweep& s, const std::vector<nlohmann::json>& values) {
    std::string out;
    for (std::size_t i = 0; i < values.size(); ++i)
        out += (i ? ", " : "") + s.sets[i].path + "=" + values[i].dump();
    return out;
}

} // namespace

Sweep make_sweep(const std::string& scene_argument, const std::vector<std::string>& sets) {
    Sweep sweep;
    const nlohmann::json base = scene_json(scene_argument, sweep.source);
    std::size_t combinations = 1;
    for (const std::string& text : sets) {
        sweep.sets.push_back(parse_set(text));
        combinations *= sweep.sets.back().values.size();
        if (combinations > kMaxSweepScenes)
            throw io::BadInput("--set " + text + ": the sweep would have more than " +
                               std::to_string(kMaxSweepScenes) + " scenes");
    }
    // Each value alone first, so that an error names the one --set at fault.
    for (const SweepSet& set : sweep.sets)
        for (const nlohmann::json& value : set.values) {
            nlohmann::json scene = base;
            apply_set(scene, set, value, sweep.source);
            check_scene(scene, sweep.source, "--set " + set.path + "=" + value.dump());
        }
    const std::size_t width = std::max<std::size_t>(3, std::to_string(combinations - 1).size());
    for (std::size_t n = 0; n < combinations; ++n) {
        io::InterruptGuard::stop_if_requested("the sweep's checks");
        SweepScene s;
        std::size_t rest = n;
        s.values.resize(sweep.sets.size());
        for (std::size_t i = sweep.sets.size(); i-- > 0;) { // the last set varies fastest
            s.values[i] = sweep.sets[i].values[rest % sweep.sets[i].values.size()];
            rest /= sweep.sets[i].values.size();
        }
        s.scene = base;
        for (std::size_t i = 0; i < sweep.sets.size(); ++i)
            apply_set(s.scene, sweep.sets[i], s.values[i], sweep.source);
        const std::string settings = describe_values(sweep, s.values);
        check_scene(s.scene, sweep.source, "the combination " + settings);
        anchor_meshes(s.scene, sweep.source);
        const std::string title = s.scene.value("title", std::string());
        s.scene["title"] = (title.empty() ? "" : title + " ") + "[" + settings + "]";
        const std::string number = std::to_string(n);
        s.file = "scene_" + std::string(width - number.size(), '0') + number + ".json";
        sweep.scenes.push_back(std::move(s));
    }
    return sweep;
}

nlohmann::json sweep_manifest(const Sweep& sweep) {
    nlohmann::json m;
    m["source"] = sweep.source;
    m["sets"] = nlohmann::json::array();
    for (const SweepSet& s : sweep.sets) m["sets"].push_back(s.text);
    m["scenes"] = nlohmann::json::array();
    for (const SweepScene& s : sweep.scenes) {
        nlohmann::json entry{{"file", s.file}, {"set", nlohmann::json::object()}};
        for (std::size_t i = 0; i < s.values.size(); ++i)
            entry["set"][sweep.sets[i].path] = s.values[i];
        m["scenes"].push_back(entry);
    }
    return m;
}

namespace {

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

} // namespace

void write_sweep(const Sweep& sweep, const fs::path& output) {
    const fs::path dir = output.filename().empty() ? output.parent_path() : output;
    std::error_code ec;
    if (fs::exists(dir, ec) && !(fs::is_directory(dir, ec) && fs::is_empty(dir, ec)))
        throw io::BadInput("sweep -o " + output.string() +
                           ": it exists and is not an empty folder; choose another folder");
    if (!dir.parent_path().empty()) {
        try {
            io::ensure_writable_directory(dir.parent_path());
        } catch (const io::FileError& e) {
            throw io::BadInput(std::string("sweep -o: ") + e.what());
        }
    }
    const fs::path temp = io::temporary_path_for(dir);
    fs::remove_all(temp, ec);
    fs::create_directory(temp);
    try {
        for (const SweepScene& s : sweep.scenes) {
            io::InterruptGuard::stop_if_requested("the sweep's writing");
            write_text(temp / s.file, s.scene.dump(2) + "\n");
        }
        write_text(temp / "manifest.json", sweep_manifest(sweep).dump(2) + "\n");
        fs::rename(temp, dir); // replaces an empty folder, atomically
    } catch (const io::Interrupted&) {
        fs::remove_all(temp, ec);
        throw;
    } catch (const std::exception& e) {
        fs::remove_all(temp, ec);
        throw std::runtime_error("cannot write the sweep into '" + output.string() +
                                 "': " + e.what());
    }
}

} // namespace tumble::app
