#pragma once
// sRGB <-> linear light (IEC 61966-2-1), on the CPU: colours people pick are sRGB, lighting adds
// in linear units (see assets/shaders/common.glsl). Converted once per instance or per frame
// here rather than per vertex or pixel on the rasteriser.
#include <glm/glm.hpp>

#include <cmath>

namespace tumble::render {

inline float srgb_to_linear(float c) {
    c = c < 0.0f ? 0.0f : c;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline glm::vec3 srgb_to_linear(glm::vec3 c) {
    return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)};
}

// The sky gradient's two ends (linear) for a background colour (sRGB): paler towards the horizon
// (haze, 40% of the way to white), deeper and more saturated overhead (the colour squared).
struct SkyColours {
    glm::vec3 horizon, zenith;
};

inline SkyColours sky_colours(glm::vec3 background_srgb) {
    const glm::vec3 base = srgb_to_linear(background_srgb);
    return {glm::mix(base, glm::vec3(1.0f), 0.4f), base * base};
}

} // namespace tumble::render
