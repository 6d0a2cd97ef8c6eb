// `tumble scenes`: the built-in scenes with their titles (the lessons' scenes last); `tumble
// scenes --show NAME` prints one's JSON as it is embedded, to start a scene of your own from
// (`tumble scenes --show default > mine.json`; the meshes it names are found built in too).
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/scene/assets.h"
#include "app/scene/scene.h"
#include "io/bad_input.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace tumble::app {
namespace {

int run_list_scenes() {
    const std::vector<std::string> names = builtin_scene_names();
    int width = 20; // the longest name ("lessons/intermediate_axis") sets the column
    for (const std::string& name : names) width = std::max(width, static_cast<int>(name.size()));
    for (const std::string& name : names) {
        try {
            const Scene s = load_scene_argument(name);
            std::printf("%-*s %s\n", width, name.c_str(), s.title.c_str());
        } catch (const std::exception& e) { // list the others all the same
            std::printf("%-*s (invalid: %s)\n", width, name.c_str(), e.what());
        }
    }
    return kOk;
}

// "default", "default.json", "builtin:default.json" or "lessons/top_precession".
int run_show_scene(std::string name) {
    if (name.starts_with("builtin:")) name.erase(0, 8);
    const std::string file = name.ends_with(".json") ? name : name + ".json";
    const std::string_view text = assets::find(file);
    if (text.empty()) {
        std::string names;
        for (const std::string& n : builtin_scene_names()) names += (names.empty() ? "" : ", ") + n;
        throw io::BadInput("--show " + name +
                           ": no built-in scene of that name (built-in scenes: " + names + ")");
    }
    std::fwrite(text.data(), 1, text.size(), stdout);
    if (!text.ends_with('\n')) std::fputc('\n', stdout);
    if (std::fflush(stdout) != 0) throw std::runtime_error("cannot write the scene to stdout");
    return kOk;
}

} // namespace

Subcommand add_scenes_command(CLI::App& app) {
    CLI::App* s = app.add_subcommand("scenes", "list the built-in scenes, or print one's JSON");
    auto show = std::make_shared<std::string>();
    auto* option = s->add_option("--show", *show,
                                 "print this built-in scene's JSON (e.g. default, "
                                 "lessons/intermediate_axis), to start a scene file from");
    return {[s] { return s->parsed(); },
            [show, option] { return option->count() ? run_show_scene(*show) : run_list_scenes(); }};
}

} // namespace tumble::app
