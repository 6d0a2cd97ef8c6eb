// `tumble scenes`: the built-in scenes with their titles.
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/scene/scene.h"

#include <cstdio>

namespace tumble::app {
namespace {

int run_list_scenes() {
    for (const std::string& name : builtin_scene_names()) {
        try {
            const Scene s = load_scene_argument(name);
            std::printf("%-20s %s\n", name.c_str(), s.title.c_str());
        } catch (const std::exception& e) { // list the others all the same
            std::printf("%-20s (invalid: %s)\n", name.c_str(), e.what());
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
