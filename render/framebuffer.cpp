#include "render/framebuffer.h"

#include "render/render_error.h"

#include <GL/glext.h>

#include <algorithm>
#include <string>
#include <utility>

namespace tumble::render {

Framebuffer::Framebuffer(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples) {
    // A renderbuffer is an image the GPU can draw into but not sample; right for buffers we
    // only read back or resolve (the shadow map, which is sampled, is a texture instead).
    const GLsizei n = samples > 1 ? samples : 0;
    glGenRenderbuffers(1, &color_);
    glBindRenderbuffer(GL_RENDERBUFFER, color_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, n, GL_RGBA8, width, height);
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, n, GL_DEPTH_COMPONENT24, width, height);

    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        destroy();
        throw RenderError("framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                          " is incomplete (glCheckFramebufferStatus = " + std::to_string(status) +
                          ")");
    }
}

Framebuffer::~Framebuffer() {
    destroy();
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : fbo_(std::exchange(other.fbo_, 0)), color_(std::exchange(other.color_, 0)),
      depth_(std::exchange(other.depth_, 0)), width_(std::exchange(other.width_, 0)),
      height_(std::exchange(other.height_, 0)), samples_(std::exchange(other.samples_, 1)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
    if (this != &other) {
        destroy();
        fbo_ = std::exchange(other.fbo_, 0);
        color_ = std::exchange(other.color_, 0);
        depth_ = std::exchange(other.depth_, 0);
        width_ = std::exchange(other.width_, 0);
        height_ = std::exchange(other.height_, 0);
        samples_ = std::exchange(other.samples_, 1);
    }
    return *this;
}

void Framebuffer::destroy() {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (color_) glDeleteRenderbuffers(1, &color_);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
    fbo_ = color_ = depth_ = 0;
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
}

void Framebuffer::resolve_into(const Framebuffer& target) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, target.width_, target.height_,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void Framebuffer::read_rgb(Image& out) const {
    if (out.width != width_ || out.height != height_) out = Image(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1); // rows of width*3 bytes, no padding to 4
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, out.rgb.data());
    // Flip in place: swap row y with row height-1-y for the top half.
    const std::size_t row_bytes = std::size_t(width_) * 3;
    for (int y = 0; y < height_ / 2; ++y) {
        std::swap_ranges(out.row(y), out.row(y) + row_bytes, out.row(height_ - 1 - y));
    }
}

} // namespace tumble::render
