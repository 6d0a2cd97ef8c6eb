// lit.vert: places one instance of a mesh in the world and on the screen. Drawn instanced: the
// mesh's vertices come from attributes 0-1, the instance's transform, colour and material from
// attributes 2-10 (render/batches.h, InstanceData). Outputs feed lit.frag.

layout(location = 0) in vec3 a_position; // unit-mesh space
layout(location = 1) in vec3 a_normal;
layout(location = 2) in mat4 i_model;         // unit mesh -> world (Instance::transform)
layout(location = 6) in mat3 i_normal_matrix; // inverse-transpose of i_model's 3x3: keeps normals
                                              // perpendicular under non-uniform scale
layout(location = 9) in vec4 i_color;         // sRGB base colour; a = 1 on the checkered ground
layout(location = 10) in vec4 i_material;     // shininess, specular, metallic, gloss (1-roughness)

uniform mat4 u_view_proj;  // world -> clip (projection * view)
uniform vec3 u_background; // sRGB, for the fog and reflection colours

out vec3 v_world;  // world-space position, for lighting and the ground checker
out vec3 v_normal; // world-space normal, not yet unit length
// Constant over the instance, so computed here once per vertex rather than once per pixel, and
// passed `flat` (not interpolated): the base colour and the sky colours, all linear.
flat out vec3 v_albedo;
flat out vec3 v_horizon;
flat out vec3 v_zenith;
flat out vec4 v_material;
flat out float v_checker;

#ifdef SHADOWS
uniform mat4 u_light_view_proj; // world -> light clip space (orthographic)
uniform vec3 u_light_dir;       // unit direction the light travels
uniform float u_normal_offset;  // metres, about one shadow-map texel
out vec3 v_shadow;              // shadow-map coordinates (xy) and depth (z) in [0, 1]
#endif

void main() {
    vec4 world = i_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = i_normal_matrix * a_normal;
    v_albedo = srgb_to_linear(i_color.rgb);
    v_checker = i_color.a;
    v_material = i_material;
    v_horizon = sky_horizon(u_background);
    v_zenith = sky_zenith(u_background);
#ifdef SHADOWS
    // Normal offset (Holbein's "normal offset shadows"): look the shadow up from a point pushed
    // off the surface, more where the light grazes it, so a surface never shadows itself.
    vec3 n = normalize(v_normal);
    float grazing = 1.0 - abs(dot(n, u_light_dir));
    vec4 light_clip = u_light_view_proj * vec4(v_world + n * (u_normal_offset * grazing), 1.0);
    v_shadow = light_clip.xyz * 0.5 + 0.5; // orthographic: w = 1
#endif
    gl_Position = u_view_proj * world;
}
