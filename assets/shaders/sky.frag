// sky.frag: the gradient sky of common.glsl, seen along this pixel's view direction.

in vec3 v_dir;
flat in vec3 v_horizon;
flat in vec3 v_zenith;

out vec4 frag_color;

void main() { frag_color = vec4(linear_to_srgb(sky_gradient(v_dir, v_horizon, v_zenith)), 1.0); }
