// shadow.vert: a shadow caster seen from the light (render/shadow_map.h). Same instance layout
// as lit.vert; only the transform is needed.

layout(location = 0) in vec3 a_position;
layout(location = 2) in mat4 i_model;

uniform mat4 u_light_view_proj;

void main() { gl_Position = u_light_view_proj * (i_model * vec4(a_position, 1.0)); }
