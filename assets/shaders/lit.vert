// lit.vert: places one instance of a mesh in the world and on the screen. Drawn instanced: the
// mesh's vertices come from attributes 0-1, the instance's transform, colour and material from
// attributes 2-10 (render/batches.h, InstanceData). Outputs feed lit.frag.

layout(location = 0) in vec3 a_position; // unit-mesh space
layout(location = 1) in vec3 a_normal;
layout(location = 2) in mat4 i_model;         // unit mesh -> world (Instance::transform)
layout(location = 6) in mat3 i_normal_matrix; // inverse-transpose of i_model's 3x3: keeps normals
                                              // perpendicular under non-uniform scale
layout(location = 9) in vec4 i_color;         // linear base colour; a = 1 on the checkered ground
layout(location = 10) in vec4 i_material;     // shininess, specular, metallic, gloss (1-roughness)

uniform mat4 u_view_proj; // world -> clip (projection * view)

out vec3 v_world;  // world-space position, for lighting, fog and the ground checker
out vec3 v_normal; // world-space normal, not yet unit length
out vec2 v_local;  // unit-mesh x, y: on the ground, where in the square [-1, 1]^2 this point is
// Constant over the instance: passed `flat` (not interpolated).
flat out vec3 v_albedo;
flat out vec4 v_material;
flat out float v_checker;

#ifdef SHADOWS
uniform mat4 u_shadow_matrix;  // world -> shadow-map coordinates (xy) and depth (z), [0, 1]
uniform vec3 u_light_dir;      // unit direction the light travels
uniform float u_normal_offset; // metres, about one shadow-map texel
out vec3 v_shadow;             // shadow-map coordinates (xy) and depth (z) in [0, 1]
#endif

void main() {
    vec4 world = i_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = i_normal_matrix * a_normal;
    v_local = a_position.xy;
    v_albedo = i_color.rgb;
    v_checker = i_color.a;
    v_material = i_material;
#ifdef SHADOWS
    // Normal offset (Holbein's "normal offset shadows"): look the shadow up from a point pushed
    // off the surface, more where the light grazes it, so a surface never shadows itself.
    vec3 n = normalize(v_normal);
    float grazing = 1.0 - abs(dot(n, u_light_dir));
    v_shadow = (u_shadow_matrix * vec4(v_world + n * (u_normal_offset * grazing), 1.0)).xyz;
#endif
    gl_Position = u_view_proj * world;
}
