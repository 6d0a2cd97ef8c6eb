// lit.frag: Blinn-Phong shading of one surface point with the scene's key light plus ambient,
// in linear light (see common.glsl), with a checker on the ground and fog in the distance.

in vec3 v_world;
in vec3 v_normal;
flat in vec3 v_albedo;  // linear base colour
flat in vec3 v_horizon; // linear sky colours, for the fog
flat in vec3 v_zenith;

out vec4 frag_color;

uniform bool u_checker;     // true for the ground plane: modulate by a checkerboard
uniform float u_specular;   // strength of the highlight (0 = matte)
uniform float u_shininess;  // Blinn-Phong exponent: larger = smaller, sharper highlight
uniform vec3 u_camera_pos;  // world
uniform vec3 u_light_dir;   // unit direction the light travels, world
uniform vec3 u_light_color; // linear
uniform float u_ambient;    // fraction of the base colour lit by ambient light

const float kSquare = 0.5;       // checker square size, metres
const float kCheckerDark = 0.82; // dark squares' brightness relative to light ones: subtle
const float kFogDistance = 60.0; // metres; fog covers 63% of the colour at this distance

// A checkerboard of unit squares: 1 on light squares, 0 on dark ones. Averaged over the pixel's
// footprint `w` (box filter, after Inigo Quilez), so far squares blend smoothly to grey instead
// of flickering into moire: the integral of a square wave is a triangle wave, so the average
// over [p - w/2, p + w/2] is a difference of triangle waves divided by w.
float checker(vec2 p) {
    vec2 w = max(fwidth(p), vec2(1e-4));
    vec2 a = abs(fract((p - 0.5 * w) * 0.5) - 0.5); // triangle wave at the footprint's two ends
    vec2 b = abs(fract((p + 0.5 * w) * 0.5) - 0.5);
    vec2 i = 2.0 * (a - b) / w; // per axis: the +1/-1 square wave averaged over the footprint
    return 0.5 - 0.5 * i.x * i.y;
}

void main() {
    vec3 albedo = v_albedo;
    if (u_checker) albedo *= mix(kCheckerDark, 1.0, checker(v_world.xy / kSquare));

    // Unit vectors at this point: surface normal n (flipped when we see the back of a plane),
    // towards the light l, towards the eye v, and the half-vector h between l and v.
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    vec3 l = -u_light_dir;
    vec3 v = normalize(u_camera_pos - v_world);
    vec3 h = normalize(l + v);

    // Ambient: light from everywhere, a little stronger from the sky above than from the ground.
    float sky_facing = 0.5 + 0.5 * n.z;
    vec3 ambient = u_ambient * mix(0.6, 1.0, sky_facing) * albedo;
    // Diffuse (Lambert): proportional to the cosine between normal and light.
    float n_dot_l = max(dot(n, l), 0.0);
    vec3 diffuse = n_dot_l * albedo * u_light_color;
    // Specular (Blinn): bright where the normal lines up with the half-vector; none on the side
    // facing away from the light.
    float highlight = n_dot_l > 0.0 ? pow(max(dot(n, h), 0.0), u_shininess) : 0.0;
    vec3 specular = u_specular * highlight * u_light_color;

    vec3 color = ambient + diffuse + specular;

    // Fog: blend towards the sky seen in the same direction, more with (squared) distance.
    float d = length(u_camera_pos - v_world) / kFogDistance;
    color = mix(color, sky_gradient(-v, v_horizon, v_zenith), 1.0 - exp(-d * d));

    frag_color = vec4(linear_to_srgb(color), 1.0);
}
