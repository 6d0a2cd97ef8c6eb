#pragma once
// What the renderer throws when GL fails: the context cannot be made, a shader does not compile,
// a framebuffer is incomplete. Apart from renderer.h so that the low-level files (context,
// shaders, framebuffer, shadow map) depend on nothing above them.
#include <stdexcept>

namespace tumble::render {

struct RenderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace tumble::render
