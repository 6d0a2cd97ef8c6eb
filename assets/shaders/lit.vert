// lit.vert: places one mesh instance in the world and on the screen.
// Inputs are the unit mesh's vertices (render/mesh.h); outputs feed lit.frag.

layout(location = 0) in vec3 a_position; // unit-mesh space
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;         // unit mesh -> world (Instance::transform)
uniform mat3 u_normal_matrix; // inverse-transpose of u_model's 3x3: keeps normals perpendicular
                              // to the surface under non-uniform scale (a flattened box)
uniform mat4 u_view_proj;     // world -> clip (projection * view)
uniform vec3 u_color;         // sRGB base colour of the instance
uniform vec3 u_background;    // sRGB, for the fog colour

out vec3 v_world;  // world-space position, for lighting and the ground checker
out vec3 v_normal; // world-space normal, not yet unit length
// Constant over the instance, so computed here once per vertex rather than once per pixel, and
// passed `flat` (not interpolated): the base colour and the sky colours, all linear.
flat out vec3 v_albedo;
flat out vec3 v_horizon;
flat out vec3 v_zenith;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    v_albedo = srgb_to_linear(u_color);
    v_horizon = sky_horizon(u_background);
    v_zenith = sky_zenith(u_background);
    gl_Position = u_view_proj * world;
}
