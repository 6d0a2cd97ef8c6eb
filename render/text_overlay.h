#pragma once
// The text overlay: lines of ASCII text in the top-left corner of the image, white on a
// translucent dark panel, drawn with DejaVu Sans Mono (assets/fonts, embedded) rasterised by
// stb_truetype into a glyph atlas once, when the overlay is made. Monospaced, so numbers that
// change every frame do not make the text jiggle.
#include "render/scene_view.h"
#include "render/shader.h"
#include "render/vertex_stream.h"

#include <GL/gl.h>

#include <array>
#include <string>
#include <vector>

namespace tumble::render {

class TextOverlay {
  public:
    // Bakes the font at a size that suits an image of `image_width` x `image_height` pixels: 1/40
    // of the height (18 pixels at 720p), but no more than 1/32 of the width, so that a narrow
    // image (a tile of `render --compare`) keeps most of its picture; at least 9 pixels. At 11
    // pixels on a 320 x 180 tile the panel covered 80% of it. Needs a current GL context; throws
    // RenderError if the font is missing.
    TextOverlay(int image_width, int image_height);
    ~TextOverlay();
    TextOverlay(const TextOverlay&) = delete;
    TextOverlay& operator=(const TextOverlay&) = delete;

    // Draws over whatever is in the bound framebuffer (blending on, depth test off).
    void draw(const std::vector<std::string>& lines, int width, int height);
    // Draws a canvas (charts) the same way: its rectangles, its polylines as quads of their
    // width, and its labels in this font.
    void draw(const Canvas& canvas, int width, int height);
    float pixel_height() const { return pixel_height_; }

  private:
    struct Glyph {
        float x0, y0, x1, y1; // atlas rectangle, pixels
        float xoff, yoff, advance;
    };
    void quad(float x0, float y0, float x1, float y1, float u0, float v0, float u1, float v1,
              const float* rgba);
    void text(float x, float baseline, const std::string& line, const float* rgba);
    void segment(glm::vec2 a, glm::vec2 b, float width, const float* rgba);
    void submit(int width, int height); // draws vertices_

    float pixel_height_ = 0;
    int atlas_width_ = 0, atlas_height_ = 0;
    std::array<Glyph, 95> glyphs_{}; // ' ' .. '~'
    float ascent_ = 0, line_height_ = 0;
    ShaderProgram program_;
    GLint viewport_uniform_ = -1;
    GLuint texture_ = 0;
    VertexStream stream_{2, 2, 4}; // pixel x, y; atlas u, v; r, g, b, a
    std::vector<float> vertices_;  // 8 floats per vertex: x, y, u, v, r, g, b, a
};

} // namespace tumble::render
