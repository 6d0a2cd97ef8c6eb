// `tumble --version`: the version, the build (app/cluster/build_id.h: checkpoints and video shards
// record it), and the OpenGL renderer this machine gives (golden images record it: frames are
// promised bit-identical only for the same GL_RENDERER and GL_VERSION).
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/cluster/build_id.h"
#include "render/renderer.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace tumble::app {
namespace {

int run_version() {
    std::printf("tumble %s\nbuild: %s\n", TUMBLE_VERSION, build_id().c_str());
    std::unique_ptr<render::Renderer> probe;
    try {
        probe = std::make_unique<render::Renderer>(render::RenderOptions{16, 16});
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("no OpenGL context: ") + e.what());
    }
    std::printf("GL_RENDERER: %s\nGL_VERSION: %s\n", probe->gl_renderer().c_str(),
                probe->gl_version().c_str());
    return kOk;
}

} // namespace

Subcommand add_version_flag(CLI::App& app) {
    auto given = std::make_shared<bool>(false);
    app.add_flag("--version", *given, "print the version and the OpenGL renderer, then exit");
    return {[given] { return *given; }, [] { return run_version(); }};
}

} // namespace tumble::app
