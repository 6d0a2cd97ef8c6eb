// `tumble scenes` and `tumble --version`.
#include "app/commands.h"
#include "app/scene.h"
#include "app/scene_options.h"
#include "render/renderer.h"

#include <cstdio>

namespace tumble::app {

int run_list_scenes() {
    for (const std::string& name : builtin_scene_names()) {
        try {
            const Scene s = load_scene_argument(name);
            std::printf("%-20s %s\n", name.c_str(), s.title.c_str());
        } catch (const std::exception& e) {
            std::printf("%-20s (invalid: %s)\n", name.c_str(), e.what());
        }
    }
    return kOk;
}

int run_version() {
    std::printf("tumble %s\n", TUMBLE_VERSION);
    try {
        render::Renderer probe({16, 16});
        std::printf("GL_RENDERER: %s\nGL_VERSION: %s\n", probe.gl_renderer().c_str(),
                    probe.gl_version().c_str());
    } catch (const std::exception& e) {
        return report_error(std::string("no OpenGL context: ") + e.what(), kRunFailed);
    }
    return kOk;
}

} // namespace tumble::app
