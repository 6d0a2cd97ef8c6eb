// A broken shader fails loudly, naming the file, instead of drawing nothing.
#include "render/gl_context.h"
#include "render/renderer.h"
#include "render/shader.h"

#include <gtest/gtest.h>

#include <string>

namespace tumble::render {
namespace {

TEST(RendererShader, CompileErrorNamesTheShader) {
    GlContext context;
    const ShaderSource vert = shader_asset("lit.vert");
    const ShaderSource broken{"broken.frag", "out vec4 c;\nvoid main() { c = undefined_thing; }\n"};
    try {
        ShaderProgram program(vert, broken);
        FAIL() << "expected a RenderError";
    } catch (const RenderError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("broken.frag"), std::string::npos) << what;
        EXPECT_NE(what.find("undefined_thing"), std::string::npos) << what;
    }
}

TEST(RendererShader, MissingAssetIsAClearError) {
    EXPECT_THROW(shader_asset("no_such_shader.frag"), RenderError);
}

TEST(RendererShader, EmbeddedShadersLink) {
    GlContext context;
    EXPECT_NE(ShaderProgram(shader_asset("lit.vert"), shader_asset("lit.frag")).id(), 0u);
    EXPECT_NE(ShaderProgram(shader_asset("sky.vert"), shader_asset("sky.frag")).id(), 0u);
}

} // namespace
} // namespace tumble::render
