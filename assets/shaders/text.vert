// text.vert: the overlay's quads (glyphs and their backing panel), given in pixels from the
// top-left corner of the image (render/text_overlay.h).

layout(location = 0) in vec2 a_pixel;
layout(location = 1) in vec2 a_uv;    // glyph atlas coordinates; negative: a solid quad
layout(location = 2) in vec4 a_color; // sRGB colour and opacity

uniform vec2 u_viewport; // image size, pixels

out vec2 v_uv;
flat out vec4 v_color;

void main() {
    v_uv = a_uv;
    v_color = a_color;
    gl_Position = vec4(2.0 * a_pixel.x / u_viewport.x - 1.0, 1.0 - 2.0 * a_pixel.y / u_viewport.y,
                       0.0, 1.0);
}
