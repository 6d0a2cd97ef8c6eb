// common.glsl: helpers shared by every shader. The loader (render/shader.cpp) compiles each
// shader as "#version 330 core" + this file + the shader's own file, because GLSL 3.30 has no
// #include.

// --- Colour spaces ----------------------------------------------------------------------------
// Colours people pick (Instance::color, SceneView::background) are sRGB: the numbers follow a
// perceptual curve, roughly value = light^(1/2.2). Light, though, adds up in *linear* units: two
// lamps give twice the photons, not twice the sRGB number. So every shader converts its inputs
// to linear, does the lighting there, and converts the result back to sRGB for the 8-bit image.
// These are the exact sRGB curves: a straight segment near black, a 2.4 power elsewhere.
vec3 srgb_to_linear(vec3 c) {
    c = max(c, 0.0); // pow() of a negative number is NaN
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c));
}

vec3 linear_to_srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0); // an 8-bit image cannot hold more than white
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

// --- Sky --------------------------------------------------------------------------------------
// The sky is a vertical gradient made from the scene's one background colour: paler towards the
// horizon (haze), deeper overhead (the colour squared: darker and more saturated). Distant
// surfaces fade towards the same gradient (fog in lit.frag), so the ground's far edge melts into
// the horizon. The two end colours are linear and the same for every pixel, so the vertex shaders
// compute them (sky_horizon, sky_zenith) and the fragment shaders only blend (sky_gradient):
// pow() is the costliest thing a CPU rasteriser runs per pixel.
vec3 sky_horizon(vec3 background_srgb) {
    return mix(srgb_to_linear(background_srgb), vec3(1.0), 0.4);
}

vec3 sky_zenith(vec3 background_srgb) {
    vec3 base = srgb_to_linear(background_srgb);
    return base * base;
}

// `dir` is a world-space view direction (z up), any length.
vec3 sky_gradient(vec3 dir, vec3 horizon, vec3 zenith) {
    float elevation = clamp(dir.z / length(dir), 0.0, 1.0); // sine of the angle above horizon
    return mix(horizon, zenith, sqrt(elevation));           // sqrt: keeps the haze band thin
}
