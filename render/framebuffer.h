#pragma once
// An off-screen framebuffer object the renderer owns: a colour renderbuffer (RGBA8) and a depth
// renderbuffer (24 bits), optionally multisampled (MSAA: each pixel keeps `samples` coverage and
// depth samples, averaged by resolve_into()). Move-only; needs a current GL context.
#include "render/image.h"

#include <GL/gl.h>

namespace tumble::render {

class Framebuffer {
  public:
    Framebuffer() = default;
    // Throws RenderError if the FBO is incomplete. samples = 1: an ordinary framebuffer.
    Framebuffer(int width, int height, int samples = 1);
    ~Framebuffer();
    Framebuffer(Framebuffer&& other) noexcept;
    Framebuffer& operator=(Framebuffer&& other) noexcept;

    void bind() const; // as the draw and read target, with the viewport covering it

    // Copies the colour buffer into `out` (RGB8, resized only if its size differs), flipping the
    // rows: glReadPixels returns the bottom row first, Image stores the top row first.
    // Single-sample framebuffers only.
    void read_rgb(Image& out) const;
    // Averages each pixel's samples into `target` (same size, single-sample): the MSAA resolve.
    void resolve_into(const Framebuffer& target) const;

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }

  private:
    void destroy();

    GLuint fbo_ = 0, color_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0, samples_ = 1;
};

} // namespace tumble::render
