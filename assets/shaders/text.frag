// text.frag: a glyph's coverage from the font atlas (one channel) as the opacity of the colour.
// Blending happens on the sRGB-encoded image, as text renderers usually do.

in vec2 v_uv;
flat in vec4 v_color;

uniform sampler2D u_atlas;

out vec4 frag_color;

void main() {
    float coverage = v_uv.x < 0.0 ? 1.0 : texture(u_atlas, v_uv).r;
    frag_color = vec4(v_color.rgb, v_color.a * coverage);
}
