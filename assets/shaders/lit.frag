// lit.frag: shades one surface point, in linear light (see common.glsl):
//   key light   Lambert diffuse + Blinn-Phong highlight, darkened where the shadow map says a
//               caster is in the way (SHADOWS), with edges that harden towards the contact
//               (SOFT_SHADOWS)
//   ambient     light from the sky (more on faces turned up) on the diffuse colour, less where a
//               nearby body hides the sky (AMBIENT_OCCLUSION)
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
flat in vec4 v_occluder[6]; // the two nearest other bodies as ellipsoids (common.glsl)

out vec4 frag_color;

uniform vec3 u_camera_pos;  // world
uniform vec3 u_light_dir;   // unit direction the light travels, world
uniform vec3 u_light_color; // linear
uniform float u_ambient;    // fraction of the base colour lit by ambient light
uniform float u_mirror;     // 1 in the reflection pass (renderer.cpp), 0 otherwise
uniform vec4 u_clip_plane;  // the mirror's plane (xyz its unit normal) in the reflection pass

const float kSquare = 0.5;       // checker square size, metres
const float kCheckerDark = 0.74; // dark squares' brightness relative to light ones
const float kFogDistance = 60.0; // metres; fog covers 63% of the colour at this distance
const float kFloorReflectance = 0.2; // of a reflecting floor, head-on

#ifdef SHADOWS
in vec3 v_shadow;
uniform sampler2DShadow u_shadow_map;
uniform float u_shadow_texel; // one texel in texture coordinates

// Percentage-closer filter (Reeves et al. 1987) over about 2k + 1 texels: each lookup of a
// sampler2DShadow with linear filtering blends the comparisons of the 2x2 nearest texels; four
// of them k/2 texels either side of the point make, for k = 1, a 3x3-texel tent, a soft edge
// about two texels wide. Wider (soft shadows) the four spread apart: at k = 2.5 their 2x2
// footprints just touch, and the edge shows two faint steps instead of a smooth ramp. More
// lookups would smooth it, but llvmpipe runs every lookup for every pixel (a branch saves
// nothing when a neighbour takes it) at about 2 ms per 720p frame each.
float pcf(float k) {
    vec2 d = vec2(0.5 * k * u_shadow_texel);
    return 0.25 * (texture(u_shadow_map, vec3(v_shadow.xy + vec2(-d.x, -d.y), v_shadow.z)) +
                   texture(u_shadow_map, vec3(v_shadow.xy + vec2(d.x, -d.y), v_shadow.z)) +
                   texture(u_shadow_map, vec3(v_shadow.xy + vec2(-d.x, d.y), v_shadow.z)) +
                   texture(u_shadow_map, vec3(v_shadow.xy + vec2(d.x, d.y), v_shadow.z)));
}

#ifdef SOFT_SHADOWS
uniform sampler2D u_shadow_depth; // the same map read as raw depths (no comparison)
uniform float u_penumbra_scale;   // penumbra width in texels per unit of map depth between
                                  // caster and receiver: 2 tan(light's angular radius) x the
                                  // map's depth range / texel size
const float kMaxSoftness = 2.0;   // texels of half-width: pcf()'s four taps stay one ramp

// Contact-hardening shadows (percentage-closer soft shadows, Fernando 2005). A light of angular
// radius a throws a penumbra of width w = 2 tan(a) (z_receiver - z_blocker): sharp where a body
// touches the ground, soft under a body high above it. 1) Blocker search: 16 raw depths around
// the point (four textureGather lookups), as far out as the widest penumbra a blocker between
// here and the light could throw; their mean over those nearer the light than the receiver is
// z_blocker. No blocker among them: the point is lit. 2) The filter above, w wide.
float light_visibility() {
    float z = v_shadow.z;
    float reach = clamp(0.5 * u_penumbra_scale * z, 1.0, kMaxSoftness);
    vec2 s = vec2(0.5 * reach * u_shadow_texel);
    vec4 g[4];
    g[0] = textureGather(u_shadow_depth, v_shadow.xy + vec2(-s.x, -s.y));
    g[1] = textureGather(u_shadow_depth, v_shadow.xy + vec2(s.x, -s.y));
    g[2] = textureGather(u_shadow_depth, v_shadow.xy + vec2(-s.x, s.y));
    g[3] = textureGather(u_shadow_depth, v_shadow.xy + vec2(s.x, s.y));
    float sum = 0.0, count = 0.0;
    for (int i = 0; i < 4; ++i) {
        vec4 blocker = step(g[i], vec4(z)); // 1 where the texel is nearer the light
        sum += dot(blocker, g[i]);
        count += dot(blocker, vec4(1.0));
    }
    if (count == 0.0) return 1.0;
    float width = (z - sum / count) * u_penumbra_scale;
    return pcf(clamp(0.5 * width, 1.0, kMaxSoftness));
}
#else
float light_visibility() { return pcf(1.0); }
#endif
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

    // Ambient: light from everywhere, a little stronger from the sky above than from the ground,
    // less where nearby bodies hide the sky.
    float sky_facing = 0.5 + 0.5 * n.z;
    float sky_seen = 1.0;
#ifdef AMBIENT_OCCLUSION
    sky_seen = (1.0 - ellipsoid_occlusion(v_world, n, v_occluder[0], v_occluder[1], v_occluder[2])) *
               (1.0 - ellipsoid_occlusion(v_world, n, v_occluder[3], v_occluder[4], v_occluder[5]));
#endif
    vec3 ambient = sky_seen * u_ambient * mix(0.6, 1.0, sky_facing) * (1.0 - 0.7 * metallic) * albedo;

    // Reflection of the surroundings, Fresnel-weighted: 4% head-on for a dielectric, the base
    // colour for a metal, rising to 100% at grazing angles.
    vec3 f0 = mix(vec3(0.04), albedo, metallic);
    float c = 1.0 - max(dot(n, v), 0.0);
    vec3 fresnel = f0 + (1.0 - f0) * (c * c * c * c * c) * gloss;
    vec3 reflection = sky_seen * specular * fresnel * environment(reflect(-v, n), gloss);

    vec3 color = key + ambient + reflection;

    // Fog: blend towards the sky seen in the same direction, more with (squared) distance.
    vec3 view = v_world - u_camera_pos;
    float fog = 1.0 - exp(-dot(view, view) * (1.0 / (kFogDistance * kFogDistance)));
    // The ground is a finite square: its outer fifth fades into the sky as the fog would, so its
    // edge melts into the horizon instead of cutting across it.
    if (v_checker > 0.5) fog = max(fog, smoothstep(0.8, 1.0, max(abs(v_local.x), abs(v_local.y))));
    color = mix(color, sky_gradient(view), fog);
    frag_color = output_color(color);
    if (u_mirror > 0.0) {
        // Seen in the floor: the fraction R that a polished floor reflects, Fresnel-weighted
        // (Schlick) from kFloorReflectance head-on towards all of it at grazing angles. Stored
        // premultiplied, with R in alpha: the floor drawn over it keeps 1 - R of its own colour
        // (renderer.cpp, the blend of the ground in scene_pass).
        float f = 1.0 - abs(dot(normalize(view), u_clip_plane.xyz));
        float r = kFloorReflectance + (1.0 - kFloorReflectance) * (f * f * f * f * f);
        frag_color = vec4(frag_color.rgb * r, r);
    }
}
