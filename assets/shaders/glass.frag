// glass.frag: a translucent surface, lit simply so that its shape reads: a soft diffuse term from
// the key light, and more opacity and a brighter rim where the surface turns away from the eye
// (a rim, as a soap bubble or a glass ball shows its outline).

in vec3 v_world;
in vec3 v_normal;

uniform vec3 u_camera_pos;
uniform vec3 u_light_dir; // unit direction the light travels
uniform vec4 u_color;     // linear colour; a: opacity where the surface faces the eye

out vec4 frag_color;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n; // the far side, seen from inside
    vec3 to_eye = normalize(u_camera_pos - v_world);
    float facing = abs(dot(n, to_eye));
    float rim = pow(1.0 - facing, 2.0);
    float diffuse = 0.45 + 0.55 * max(dot(n, -u_light_dir), 0.0);
    vec3 lit = u_color.rgb * diffuse + vec3(0.35) * rim;
    float alpha = clamp(u_color.a * (1.0 + 2.0 * rim), 0.0, 0.85);
    frag_color = vec4(output_color(lit).rgb, alpha);
}
