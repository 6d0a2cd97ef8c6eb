// sky.vert: one triangle that covers the whole screen, placed on the far plane, carrying the
// world-space view direction of each corner to sky.frag. No vertex buffer: the corners come from
// gl_VertexID (draw 3 vertices with an empty vertex array).

uniform mat4 u_inv_view_proj; // clip -> world
uniform vec3 u_camera_pos;

out vec3 v_dir; // world-space direction from the eye through this point, any length

void main() {
    // Corners (-1,-1), (3,-1), (-1,3) in normalised device coordinates: a triangle twice the
    // screen's size whose inside covers the square [-1,1]^2.
    vec2 ndc = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    // Un-project the corner on the far plane back to the world. For a perspective camera the
    // result is an affine function of ndc, so the interpolated v_dir is exact at every pixel.
    vec4 far_point = u_inv_view_proj * vec4(ndc, 1.0, 1.0);
    v_dir = far_point.xyz / far_point.w - u_camera_pos;
    gl_Position = vec4(ndc, 1.0, 1.0); // z = w: depth 1.0, behind everything drawn before
}
