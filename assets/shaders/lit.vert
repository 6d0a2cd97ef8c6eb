// lit.vert: places one instance of a mesh in the world and on the screen. Drawn instanced: the
// mesh's vertices come from attributes 0-1, the instance's transform, colour, material and its
// two nearest occluders from attributes 2-13 (render/batches.h, InstanceData). Outputs feed
// lit.frag.

layout(location = 0) in vec3 a_position; // unit-mesh space
layout(location = 1) in vec3 a_normal;
layout(location = 2) in mat4 i_model;         // unit mesh -> world (Instance::transform)
layout(location = 6) in vec4 i_color;         // linear base colour; a = 1 on the checkered ground
layout(location = 7) in vec4 i_material;      // shininess, specular, metallic, gloss (1-roughness)
layout(location = 8) in vec4 i_occluder[6];   // two ellipsoids, three rows each (common.glsl)

uniform mat4 u_view_proj; // world -> clip (projection * view)
uniform vec4 u_clip_plane; // the reflection pass keeps dot(n, x) + d >= 0 (renderer.cpp)

out vec3 v_world;  // world-space position, for lighting, fog and the ground checker
out vec3 v_normal; // world-space normal, not yet unit length
out vec2 v_local;  // unit-mesh x, y: on the ground, where in the square [-1, 1]^2 this point is
// Constant over the instance: passed `flat` (not interpolated).
flat out vec3 v_albedo;
flat out vec4 v_material;
flat out float v_checker;
flat out vec4 v_occluder[6];

#ifdef SHADOWS
uniform mat4 u_shadow_matrix;  // world -> shadow-map coordinates (xy) and depth (z), [0, 1]
uniform vec3 u_light_dir;      // unit direction the light travels
uniform float u_normal_offset; // metres, about one shadow-map texel
out vec3 v_shadow;             // shadow-map coordinates (xy) and depth (z) in [0, 1]
#endif

void main() {
    vec4 world = i_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    // Normals transform by the inverse-transpose of the model's 3x3: a box squashed in z gets
    // normals stretched in z, so they stay perpendicular to its faces. Per vertex, it costs less
    // than the three attributes it would take per instance.
    v_normal = transpose(inverse(mat3(i_model))) * a_normal;
    v_local = a_position.xy;
    v_albedo = i_color.rgb;
    v_checker = i_color.a;
    v_material = i_material;
    for (int k = 0; k < 6; ++k) v_occluder[k] = i_occluder[k];
#ifdef SHADOWS
    // Normal offset (Holbein's "normal offset shadows"): look the shadow up from a point pushed
    // off the surface, more where the light grazes it, so a surface never shadows itself.
    vec3 n = normalize(v_normal);
    float grazing = 1.0 - abs(dot(n, u_light_dir));
    v_shadow = (u_shadow_matrix * vec4(v_world + n * (u_normal_offset * grazing), 1.0)).xyz;
#endif
    gl_ClipDistance[0] = dot(u_clip_plane, vec4(world.xyz, 1.0));
    gl_Position = u_view_proj * world;
}
