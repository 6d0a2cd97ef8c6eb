// line.vert: the ribbons of world-space polylines (render/line_ribbons.h), already in clip
// space: the CPU widened each segment into a quad.

layout(location = 0) in vec4 a_clip;
layout(location = 1) in vec4 a_color; // linear colour and opacity

out vec4 v_color;

void main() {
    v_color = a_color;
    gl_Position = a_clip;
}
