// glass.vert: one translucent surface of a construction (render/glass.h), placed by its model
// matrix. Outputs feed glass.frag.

layout(location = 0) in vec3 a_position; // unit-mesh space
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;     // unit mesh -> world
uniform mat4 u_view_proj; // world -> clip

out vec3 v_world;
out vec3 v_normal; // world space, not unit length

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = transpose(inverse(mat3(u_model))) * a_normal;
    gl_Position = u_view_proj * world;
}
