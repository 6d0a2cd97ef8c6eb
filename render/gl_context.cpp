#include "render/gl_context.h"

#include "render/render_error.h"

#include <GL/gl.h>
#include <GL/osmesa.h>

namespace tumble::render {
namespace {

// The oldest GL this renderer speaks: 3.3 core gives VAOs, FBOs, GLSL 3.30 and instancing.
constexpr int kMajor = 3;
constexpr int kMinor = 3;

OSMesaContext create_core_context() {
    // Attribute list: (name, value) pairs ended by 0. The context has no depth buffer of its own:
    // depth lives in the renderer's framebuffer object.
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           kMajor,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           kMinor,
                           0};
    return OSMesaCreateContextAttribs(attribs, nullptr);
}

std::string gl_string(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

} // namespace

GlContext::GlContext() {
    context_ = create_core_context();
    if (!context_) {
        throw RenderError("OSMesa could not create an OpenGL " + std::to_string(kMajor) + "." +
                          std::to_string(kMinor) +
                          " core profile context (is libosmesa6 from Mesa >= 11.2 installed, and "
                          "is LIBGL_ALWAYS_SOFTWARE / GALLIUM_DRIVER forcing an old driver?)");
    }
    try {
        make_current();
        renderer_ = gl_string(GL_RENDERER);
        version_ = gl_string(GL_VERSION);
        GLint major = 0, minor = 0;
        glGetIntegerv(GL_MAJOR_VERSION, &major);
        glGetIntegerv(GL_MINOR_VERSION, &minor);
        if (major * 10 + minor < kMajor * 10 + kMinor) {
            throw RenderError("OSMesa gave OpenGL " + version_ + " (" + renderer_ + "); need " +
                              std::to_string(kMajor) + "." + std::to_string(kMinor) + " core");
        }
    } catch (...) {
        release();
        throw;
    }
}

GlContext::~GlContext() {
    release();
}

void GlContext::release() {
    if (!context_) return;
    // Unbind first: destroying the current context would leave the thread pointing at freed state.
    if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
    context_ = nullptr;
}

void GlContext::make_current() {
    if (OSMesaGetCurrentContext() == context_) return;
    if (!OSMesaMakeCurrent(context_, token_buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
        throw RenderError("OSMesaMakeCurrent failed to bind the OpenGL context");
    }
}

} // namespace tumble::render
