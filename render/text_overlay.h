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

// The overlay font at the size an image of `width` x `height` pixels gets: 1/40 of the height (18
// pixels at 720p), but no more than 1/32 of the width, so that a narrow image (a tile of `render
// --compare`) keeps most of its picture; at least 9 pixels, below which the glyphs stop being
// legible. Its metrics, in pixels, are what app/view lays panels out with.
struct OverlayFont {
    float pixel_height = 9.0f;
    float advance = 0.0f;     // every glyph's (monospaced)
    float ascent = 0.0f;      // baseline below a line's top
    float line_height = 0.0f; // from one baseline to the next
    float margin() const;     // from the image's edge to a panel
    float pad() const;        // from a panel's edge to its text
    // A panel holding `lines` (the text overlay's), with its pads.
    glm::vec2 panel_size(const std::vector<std::string>& lines) const;
};
// Reads the embedded font's metrics (no GL needed); throws RenderError if it is missing.
OverlayFont overlay_font(int width, int height);

class TextOverlay {
  public:
    // Bakes the font at overlay_font(image_width, image_height)'s size. Needs a current GL
    // context; throws RenderError if the font is missing.
    TextOverlay(int image_width, int image_height);
    ~TextOverlay();
    TextOverlay(const TextOverlay&) = delete;
    TextOverlay& operator=(const TextOverlay&) = delete;

    // Draws `lines` on their panel (OverlayFont::panel_size) with its top-left corner at `at`
    // (negative: the top-left corner's margin), over whatever is in the bound framebuffer
    // (blending on, depth test off).
    void draw(const std::vector<std::string>& lines, glm::vec2 at, int width, int height);
    // Draws a canvas (charts) the same way: its rectangles, its polylines as quads of their
    // width, and its labels in this font.
    void draw(const Canvas& canvas, int width, int height);
    float pixel_height() const { return font_.pixel_height; }

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

    OverlayFont font_;
    int atlas_width_ = 0, atlas_height_ = 0;
    std::array<Glyph, 95> glyphs_{}; // ' ' .. '~'
    ShaderProgram program_;
    GLint viewport_uniform_ = -1;
    GLuint texture_ = 0;
    VertexStream stream_{2, 2, 4}; // pixel x, y; atlas u, v; r, g, b, a
    std::vector<float> vertices_;  // 8 floats per vertex: x, y, u, v, r, g, b, a
};

} // namespace tumble::render
