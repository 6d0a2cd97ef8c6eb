#pragma once
// An OSMesa OpenGL context that owns itself (RAII). OSMesa renders on the CPU (llvmpipe), so a
// headless machine needs no display, no GPU and no window system to draw.
//
// OSMesa insists on a client memory buffer to make a context current. We never draw into it:
// every pass renders into framebuffer objects the renderer owns (framebuffer.h), so the OSMesa
// buffer is a token 1x1 pixel.
#include <array>
#include <cstdint>
#include <string>

struct osmesa_context; // from <GL/osmesa.h>; kept out of this header

namespace tumble::render {

class GlContext {
  public:
    // Asks for a 3.3 core profile (Mesa answers with the highest core version it has, e.g. 4.5);
    // throws RenderError with the reason when OSMesa cannot give one.
    GlContext();
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // Makes this context current on the calling thread (a no-op when it already is). GL calls
    // act on the current context, so call this before any GL work, on the thread doing it.
    void make_current();

    const std::string& renderer() const { return renderer_; } // GL_RENDERER
    const std::string& version() const { return version_; }   // GL_VERSION

  private:
    void release(); // unbinds and destroys the context; safe to call twice

    osmesa_context* context_ = nullptr;
    std::array<std::uint8_t, 4> token_buffer_{}; // the 1x1 RGBA buffer OSMesa requires
    std::string renderer_;
    std::string version_;
};

} // namespace tumble::render
