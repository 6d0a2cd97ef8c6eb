// lit.frag: shades one surface point, in linear light (see common.glsl):
//   key light   Lambert diffuse + Blinn-Phong highlight, darkened where the shadow map says a
//               caster is in the way (SHADOWS)
//   ambient     light from the sky (more on faces turned up) on the diffuse colour
//   reflection  the sky and ground mirrored in the surface, weighted by Fresnel (Schlick): strong
//               at grazing angles, blurred towards the average sky the rougher the surface
//   fog         distant points fade into the sky colour
// plus a checkerboard on the ground.

in vec3 v_world;
in vec3 v_normal;
in vec2 v_local;         // unit-mesh x, y (the ground's square is [-1, 1]^2)
flat in vec3 v_albedo;   // linear base colour
flat in vec4 v_material; // shininess, specular, metallic, gloss (1 - roughness)
flat in float v_checker; // 1 on the ground

out vec4 frag_color;

uniform vec3 u_camera_pos;  // world
uniform vec3 u_light_dir;   // unit direction the light travels, world
uniform vec3 u_light_color; // linear
uniform float u_ambient;    // fraction of the base colour lit by ambient light

const float kSquare = 0.5;       // checker square size, metres
const float kCheckerDark = 0.74; // dark squares' brightness relative to light ones
const float kFogDistance = 60.0; // metres; fog covers 63% of the colour at this distance

#ifdef SHADOWS
in vec3 v_shadow;
uniform sampler2DShadow u_shadow_map;
uniform float u_shadow_texel; // one texel in texture coordinates

// Fraction of the key light reaching this point: 1 lit, 0 in full shadow. Each lookup of a
// sampler2DShadow with linear filtering blends the comparisons of the 2x2 nearest texels; four
// of them half a texel either side of the point make a 3x3-texel tent filter, a soft edge about
// two texels (2.5 cm) wide. Each lookup costs llvmpipe about 2 ms per 720p frame.
float light_visibility() {
    vec2 d = vec2(0.5 * u_shadow_texel);
    return 0.25 * (texture(u_shadow_map, vec3(v_shadow.xy + vec2(-d.x, -d.y), v_shadow.z)) +
                   texture(u_shadow_map, vec3(v_shadow.xy + vec2(d.x, -d.y), v_shadow.z)) +
                   texture(u_shadow_map, vec3(v_shadow.xy + vec2(-d.x, d.y), v_shadow.z)) +
                   texture(u_shadow_map, vec3(v_shadow.xy + vec2(d.x, d.y), v_shadow.z)));
}
#endif

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

// What a mirror would show in direction r: the sky gradient above the horizon, a dim ground
// below, blurred towards their average as gloss goes to 0.
vec3 environment(vec3 r, float gloss) {
    vec3 ground = 0.25 * u_horizon;
    vec3 sharp = mix(ground, sky_gradient(r), smoothstep(-0.03, 0.03, r.z));
    vec3 blurred = 0.5 * (ground + 0.5 * (u_horizon + u_zenith));
    return mix(blurred, sharp, gloss);
}

void main() {
    vec3 albedo = v_albedo;
    if (v_checker > 0.5) albedo *= mix(kCheckerDark, 1.0, checker(v_world.xy / kSquare));
    float shininess = v_material.x, specular = v_material.y, metallic = v_material.z;
    float gloss = v_material.w;

    // Unit vectors at this point: surface normal n (flipped when we see the back of a plane),
    // towards the light l, towards the eye v, and the half-vector h between l and v.
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    vec3 l = -u_light_dir;
    vec3 v = normalize(u_camera_pos - v_world);
    vec3 h = normalize(l + v);

    // Key light: Lambert diffuse (none on a metal) and a Blinn-Phong highlight, tinted by the
    // base colour on a metal. (shininess + 8) / 40 keeps a small sharp highlight about as
    // bright overall as a broad one.
    float n_dot_l = max(dot(n, l), 0.0);
    float visibility = 1.0;
#ifdef SHADOWS
    if (n_dot_l > 0.0) visibility = light_visibility();
#endif
    vec3 highlight_color = mix(vec3(1.0), albedo, metallic);
    float highlight = pow(max(dot(n, h), 0.0), shininess) * min((shininess + 8.0) / 40.0, 6.0);
    vec3 key = n_dot_l * ((1.0 - metallic) * albedo + specular * highlight * highlight_color);
    key *= visibility * u_light_color;

    // Ambient: light from everywhere, a little stronger from the sky above than from the ground.
    float sky_facing = 0.5 + 0.5 * n.z;
    vec3 ambient = u_ambient * mix(0.6, 1.0, sky_facing) * (1.0 - 0.7 * metallic) * albedo;

    // Reflection of the surroundings, Fresnel-weighted: 4% head-on for a dielectric, the base
    // colour for a metal, rising to 100% at grazing angles.
    vec3 f0 = mix(vec3(0.04), albedo, metallic);
    float c = 1.0 - max(dot(n, v), 0.0);
    vec3 fresnel = f0 + (1.0 - f0) * (c * c * c * c * c) * gloss;
    vec3 reflection = specular * fresnel * environment(reflect(-v, n), gloss);

    vec3 color = key + ambient + reflection;

    // Fog: blend towards the sky seen in the same direction, more with (squared) distance.
    vec3 view = v_world - u_camera_pos;
    float fog = 1.0 - exp(-dot(view, view) * (1.0 / (kFogDistance * kFogDistance)));
    // The ground is a finite square: its outer fifth fades into the sky as the fog would, so its
    // edge melts into the horizon instead of cutting across it.
    if (v_checker > 0.5) fog = max(fog, smoothstep(0.8, 1.0, max(abs(v_local.x), abs(v_local.y))));
    frag_color = output_color(mix(color, sky_gradient(view), fog));
}
