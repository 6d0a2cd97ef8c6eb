// ao_decal.vert: one ground decal of ambient occlusion (render/ambient_occlusion.h): the plane
// mesh's unit square laid on a plane around a body's foot. Instanced: attributes 2-5 place the
// square, 6-8 are the body's occluder ellipsoid (three rows, common.glsl).

layout(location = 0) in vec3 a_position; // the unit square [-1, 1]^2 at z = 0
layout(location = 2) in mat4 i_model;    // square -> world; its z column is the plane's normal
layout(location = 6) in vec4 i_occluder[3];

uniform mat4 u_view_proj;

out vec3 v_world;
flat out vec3 v_normal;
flat out vec4 v_occluder[3];

void main() {
    vec4 world = i_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = i_model[2].xyz;
    for (int k = 0; k < 3; ++k) v_occluder[k] = i_occluder[k];
    gl_Position = u_view_proj * world;
}
