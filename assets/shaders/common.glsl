// common.glsl: helpers shared by every shader. The loader (render/shader.cpp) compiles each
// shader as "#version 330 core" + this file + the shader's own file, because GLSL 3.30 has no
// #include.

// --- Colour spaces ----------------------------------------------------------------------------
// Colours people pick (Instance::color, SceneView::background) are sRGB: the numbers follow a
// perceptual curve, roughly value = light^(1/2.2). Light, though, adds up in *linear* units: two
// lamps give twice the photons, not twice the sRGB number. So the renderer converts colours to
// linear (on the CPU, once per instance), the shaders light in linear units, and the result is
// encoded back to sRGB for the 8-bit image by output_color().
#ifdef SRGB_FRAMEBUFFER
// The framebuffer is sRGB: the GL encodes on store, and averages MSAA samples in linear light.
vec4 output_color(vec3 linear) { return vec4(linear, 1.0); }
#else
// The exact sRGB curve: a straight segment near black, a 2.4 power elsewhere.
vec4 output_color(vec3 c) {
    c = clamp(c, 0.0, 1.0); // an 8-bit image cannot hold more than white
    return vec4(mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c)), 1.0);
}
#endif

// --- Sky --------------------------------------------------------------------------------------
// The sky is a vertical gradient between two linear colours made from the scene's one background
// colour (render/renderer.cpp, sky_colours): paler towards the horizon (haze), deeper overhead.
// Distant surfaces fade towards the same gradient (fog), so the ground's far edge melts into the
// horizon. The end colours are uniforms, computed once per frame on the CPU: pow() is among the
// costliest things a CPU rasteriser runs, per vertex as much as per pixel.
uniform vec3 u_horizon; // linear
uniform vec3 u_zenith;  // linear

// `dir` is a world-space view direction (z up), any length.
vec3 sky_gradient(vec3 dir) {
    float elevation = clamp(dir.z / length(dir), 0.0, 1.0); // sine of the angle above horizon
    return mix(u_horizon, u_zenith, sqrt(elevation));       // sqrt: keeps the haze band thin
}

// --- Ambient occlusion (render/ambient_occlusion.h derives it) ---------------------------------
// The fraction of the cosine-weighted sky above point p (unit normal n) that an ellipsoid hides.
// The ellipsoid comes as three rows (row i of A, centre[i]), A mapping world offsets from its
// centre onto the unit sphere. There a sphere of radius 1 at distance l in a direction at angle
// theta from the normal hides cos(theta) / l^2 (its form factor); the normal maps by A^-T, whose
// row i is row i of A over its squared length (A's rows are orthogonal: a rotation and a scale).
// Inside the ellipsoid (l < 1) the point is buried: the occlusion rises to 1. It fades to 0
// between l = 2 and l = 3, where the occluder's reach ends.
float ellipsoid_occlusion(vec3 p, vec3 n, vec4 r0, vec4 r1, vec4 r2) {
    vec3 e = vec3(r0.w, r1.w, r2.w) - p; // point -> centre, world
    vec3 d = vec3(dot(r0.xyz, e), dot(r1.xyz, e), dot(r2.xyz, e));
    vec3 m = vec3(dot(r0.xyz, n) / dot(r0.xyz, r0.xyz), dot(r1.xyz, n) / dot(r1.xyz, r1.xyz),
                  dot(r2.xyz, n) / dot(r2.xyz, r2.xyz));
    float l = length(d);
    float occlusion = min(max(dot(normalize(m), d), 0.0) / (l * l * l), 1.0);
    occlusion = mix(occlusion, 1.0, smoothstep(1.0, 0.7, l));
    return occlusion * (1.0 - smoothstep(2.0, 3.0, l));
}
