#pragma once
// An off-screen framebuffer object the renderer owns: a colour renderbuffer (RGBA8) and a depth
// renderbuffer (24 bits). Drawing into our own FBO instead of OSMesa's buffer keeps the door open
// for later passes: a multisampled FBO resolved into this one (MSAA), a depth-only FBO rendered
// from the light (shadow map). Move-only; needs a current GL context.
#include "render/image.h"

#include <GL/gl.h>

namespace tumble::render {

class Framebuffer {
  public:
    Framebuffer() = default;
    Framebuffer(int width, int height); // throws RenderError if the FBO is incomplete
    ~Framebuffer();
    Framebuffer(Framebuffer&& other) noexcept;
    Framebuffer& operator=(Framebuffer&& other) noexcept;

    void bind() const; // as the draw and read target, with the viewport covering it

    // Copies the colour buffer into `out` (RGB8, resized only if its size differs), flipping the
    // rows: glReadPixels returns the bottom row first, Image stores the top row first.
    void read_rgb(Image& out) const;

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    void destroy();

    GLuint fbo_ = 0, color_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace tumble::render
