// sky.frag: the gradient sky of common.glsl, seen along this pixel's view direction.

in vec3 v_dir;

out vec4 frag_color;

void main() { frag_color = output_color(sky_gradient(v_dir)); }
