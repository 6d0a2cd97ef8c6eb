// `tumble scenes`: the built-in scenes with their titles (the lessons' scenes last).
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/scene/scene.h"

#include <algorithm>
#include <cstdio>

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

} // namespace

Subcommand add_scenes_command(CLI::App& app) {
    CLI::App* s = app.add_subcommand("scenes", "list the built-in scenes");
    return {[s] { return s->parsed(); }, [] { return run_list_scenes(); }};
}

} // namespace tumble::app
