// line.frag: a ribbon's colour, unlit (a drawn line, not a surface), encoded for the target.

in vec4 v_color;

out vec4 frag_color;

void main() { frag_color = vec4(output_color(v_color.rgb).rgb, v_color.a); }
