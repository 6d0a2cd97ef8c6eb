#include "render/text_overlay.h"

#include "render/assets.h"
#include "render/render_error.h"

#include <GL/glext.h>
#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace tumble::render {
namespace {

constexpr const char* kFont = "DejaVuSansMono.ttf";
constexpr int kFirstChar = 32, kCharCount = 95; // printable ASCII

const float kTextColor[4] = {1.0f, 1.0f, 1.0f, 0.95f};
const float kPanelColor[4] = {0.05f, 0.06f, 0.08f, 0.55f};

const unsigned char* font_data() {
    const std::string_view font = assets::find(kFont);
    if (font.empty()) throw RenderError(std::string("font ") + kFont + " is not embedded");
    return reinterpret_cast<const unsigned char*>(font.data());
}

} // namespace

float OverlayFont::margin() const {
    return std::round(0.8f * pixel_height);
}

float OverlayFont::pad() const {
    return std::round(0.5f * pixel_height);
}

glm::vec2 OverlayFont::panel_size(const std::vector<std::string>& lines) const {
    std::size_t columns = 0;
    for (const std::string& line : lines) columns = std::max(columns, line.size());
    return {2 * pad() + std::ceil(advance * float(columns)),
            2 * pad() + line_height * float(lines.size())};
}

OverlayFont overlay_font(int width, int height) {
    const unsigned char* data = font_data();
    OverlayFont f;
    // At 11 pixels on a 320 x 180 tile the old panel covered 80% of it; below 9 the glyphs blur.
    f.pixel_height =
        std::max(9.0f, std::round(std::min(float(height) / 40.0f, float(width) / 32.0f)));
    stbtt_fontinfo info;
    if (!stbtt_InitFont(&info, data, stbtt_GetFontOffsetForIndex(data, 0)))
        throw RenderError(std::string("cannot read the font ") + kFont);
    int ascent = 0, descent = 0, gap = 0, advance = 0, bearing = 0;
    stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
    stbtt_GetCodepointHMetrics(&info, 'M', &advance, &bearing);
    const float scale = stbtt_ScaleForPixelHeight(&info, f.pixel_height);
    f.advance = float(advance) * scale;
    f.ascent = std::round(float(ascent) * scale);
    f.line_height = std::round(float(ascent - descent + gap) * scale);
    return f;
}

TextOverlay::TextOverlay(int image_width, int image_height)
    : font_(overlay_font(image_width, image_height)),
      program_(shader_asset("text.vert"), shader_asset("text.frag")) {
    const unsigned char* data = font_data();
    const float px = font_.pixel_height;
    atlas_width_ = px > 24 ? 1024 : 512;
    atlas_height_ = px > 48 ? 1024 : 512;
    std::vector<unsigned char> atlas(std::size_t(atlas_width_) * std::size_t(atlas_height_));
    stbtt_bakedchar baked[kCharCount];
    if (stbtt_BakeFontBitmap(data, 0, px, atlas.data(), atlas_width_, atlas_height_, kFirstChar,
                             kCharCount, baked) <= 0)
        throw RenderError("the overlay font does not fit its atlas at " + std::to_string(px) +
                          " pixels");
    for (int i = 0; i < kCharCount; ++i) {
        const stbtt_bakedchar& b = baked[i];
        glyphs_[std::size_t(i)] = {float(b.x0), float(b.y0), float(b.x1), float(b.y1),
                                   b.xoff,      b.yoff,      b.xadvance};
    }

    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas_width_, atlas_height_, 0, GL_RED, GL_UNSIGNED_BYTE,
                 atlas.data());
    // Glyph quads sit on whole pixels and map texel for texel: nearest is exact.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    viewport_uniform_ = program_.uniform("u_viewport");
    glUseProgram(program_.id());
    glUniform1i(program_.uniform("u_atlas"), 0);
}

TextOverlay::~TextOverlay() {
    if (texture_) glDeleteTextures(1, &texture_);
}

void TextOverlay::quad(float x0, float y0, float x1, float y1, float u0, float v0, float u1,
                       float v1, const float* c) {
    const float corners[6][4] = {{x0, y0, u0, v0}, {x1, y0, u1, v0}, {x1, y1, u1, v1},
                                 {x0, y0, u0, v0}, {x1, y1, u1, v1}, {x0, y1, u0, v1}};
    for (const auto& k : corners)
        vertices_.insert(vertices_.end(), {k[0], k[1], k[2], k[3], c[0], c[1], c[2], c[3]});
}

void TextOverlay::draw(const std::vector<std::string>& lines, glm::vec2 at, int width, int height) {
    if (lines.empty()) return;
    vertices_.clear();
    if (at.x < 0.0f || at.y < 0.0f) at = glm::vec2(font_.margin());
    at = glm::round(at); // glyphs on whole pixels
    const glm::vec2 size = font_.panel_size(lines);
    const float pad = font_.pad();
    // The panel first, then the glyphs over it (one draw call: order within it is kept).
    quad(at.x, at.y, at.x + size.x, at.y + size.y, -1, -1, -1, -1, kPanelColor);
    float baseline = at.y + pad + font_.ascent;
    for (const std::string& line : lines) {
        text(at.x + pad, baseline, line, kTextColor);
        baseline += font_.line_height;
    }
    submit(width, height);
}

void TextOverlay::text(float x, float baseline, const std::string& line, const float* rgba) {
    const float inv_w = 1.0f / float(atlas_width_), inv_h = 1.0f / float(atlas_height_);
    for (char ch : line) {
        int index = static_cast<unsigned char>(ch) - kFirstChar;
        if (index < 0 || index >= kCharCount) index = '?' - kFirstChar;
        const Glyph& g = glyphs_[std::size_t(index)];
        if (g.x1 > g.x0) { // the space has no pixels
            const float gx = std::round(x + g.xoff), gy = std::round(baseline + g.yoff);
            quad(gx, gy, gx + (g.x1 - g.x0), gy + (g.y1 - g.y0), g.x0 * inv_w, g.y0 * inv_h,
                 g.x1 * inv_w, g.y1 * inv_h, rgba);
        }
        x += g.advance;
    }
}

// A line segment as a quad `width` pixels wide (two triangles; the joints of a polyline overlap
// by half a width, which at chart widths does not show).
void TextOverlay::segment(glm::vec2 a, glm::vec2 b, float width, const float* c) {
    const glm::vec2 d = b - a;
    const float length = glm::length(d);
    if (length <= 0.0f) return;
    const glm::vec2 along = d / length * (0.5f * width), across(-along.y, along.x);
    const glm::vec2 p[4] = {a - along - across, b + along - across, b + along + across,
                            a - along + across};
    for (int k : {0, 1, 2, 0, 2, 3})
        vertices_.insert(vertices_.end(), {p[k].x, p[k].y, -1.0f, -1.0f, c[0], c[1], c[2], c[3]});
}

void TextOverlay::draw(const Canvas& canvas, int width, int height) {
    if (canvas.empty()) return;
    vertices_.clear();
    for (const Canvas::Rect& r : canvas.rects)
        quad(r.min.x, r.min.y, r.max.x, r.max.y, -1, -1, -1, -1, &r.rgba[0]);
    for (const Canvas::Strip& s : canvas.strips)
        for (std::uint32_t i = 1; i < s.count; ++i)
            segment(canvas.points[s.first + i - 1], canvas.points[s.first + i], s.width_px,
                    &s.rgba[0]);
    const float advance = glyphs_[0].advance;
    for (const Canvas::Label& l : canvas.labels) {
        const float w = advance * float(l.text.size());
        const float x = l.align < 0 ? l.at.x : l.align == 0 ? l.at.x - 0.5f * w : l.at.x - w;
        text(x, l.at.y, l.text, &l.rgba[0]);
    }
    submit(width, height);
}

void TextOverlay::submit(int width, int height) {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(program_.id());
    glUniform2f(viewport_uniform_, float(width), float(height));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    stream_.draw_triangles(vertices_);
    glDisable(GL_BLEND);
}

} // namespace tumble::render
