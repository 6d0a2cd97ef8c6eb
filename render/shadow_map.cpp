#include "render/shadow_map.h"

#include "render/render_error.h"

#include <GL/glext.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace tumble::render {

LightFrame fit_light_frame(glm::vec3 direction, std::span<const glm::vec4> casters,
                           int max_map_size, float texel_target, float max_half_size) {
    LightFrame out;
    if (casters.empty() || max_map_size <= 0) return out;
    // Light view: looking along the light from the origin; any up not parallel to it will do.
    const glm::vec3 d = glm::normalize(direction);
    const glm::vec3 up = std::abs(d.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), d, up);

    // Bounds of the casters in light view space (the light looks down -z).
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec4& c : casters) {
        const glm::vec3 p = glm::vec3(view * glm::vec4(glm::vec3(c), 1.0f));
        lo = glm::min(lo, p - c.w);
        hi = glm::max(hi, p + c.w);
    }
    // Square footprint, half size rounded up to a power of 2^(1/4): a few sizes only, so the
    // texel grid (and with it every shadow edge) stays put while bodies move about inside.
    const float raw_half =
        std::clamp(0.5f * std::max(hi.x - lo.x, hi.y - lo.y), 0.05f, max_half_size);
    const float half = std::exp2(std::ceil(4.0f * std::log2(raw_half * 1.02f)) / 4.0f);
    // The map's size: the smallest power of two that gives texels no larger than the target, so
    // that the soft edge the shader filters over is about one texel wide (see lit.frag).
    int map_size = 64;
    while (map_size < max_map_size && 2.0f * half / float(map_size) > texel_target) map_size *= 2;
    map_size = std::min(map_size, max_map_size);
    const float texel = 2.0f * half / float(map_size);
    // Centre snapped to whole texels: moving the frustum by a fraction of a texel would move every
    // shadow edge's sampling pattern with it.
    glm::vec2 centre = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
    centre = glm::floor(centre / texel + 0.5f) * texel;
    // Depth: from just in front of the nearest caster to just behind the farthest. Receivers
    // beyond the far plane compare as "far" (the reference depth clamps to 1) and are shadowed
    // wherever a caster covers them; receivers nearer than the near plane are in front of every
    // caster and lit.
    const float margin = 0.05f * (hi.z - lo.z) + 0.01f;
    const float z_near = -hi.z - margin, z_far = -lo.z + margin;
    const glm::mat4 proj = glm::ortho(centre.x - half, centre.x + half, centre.y - half,
                                      centre.y + half, z_near, z_far);
    out.view_proj = proj * view;
    out.texel_size = texel;
    out.depth_range = z_far - z_near;
    out.map_size = map_size;
    out.empty = false;
    return out;
}

ShadowMap::ShadowMap(int size) : size_(size) {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, nullptr);
    // Linear filtering of a depth comparison: the GL compares the 4 nearest texels and blends the
    // results, a 2x2 percentage-closer filter in every lookup.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    // Outside the map there is no caster: a border at the far depth reads as lit.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[] = {1.0f, 1.0f, 1.0f, 1.0f};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);

    // The raw-depth view: a sampler object overrides the texture's comparison and filtering on
    // the unit it is bound to, and keeps the same border (far: no caster outside the map).
    glGenSamplers(1, &raw_sampler_);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(raw_sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glSamplerParameterfv(raw_sampler_, GL_TEXTURE_BORDER_COLOR, border);

    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture_, 0);
    glDrawBuffer(GL_NONE); // depth only
    glReadBuffer(GL_NONE);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &fbo_);
        glDeleteSamplers(1, &raw_sampler_);
        glDeleteTextures(1, &texture_);
        throw RenderError("shadow map " + std::to_string(size) +
                          " is incomplete (glCheckFramebufferStatus = " + std::to_string(status) +
                          ")");
    }
}

ShadowMap::~ShadowMap() {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (raw_sampler_) glDeleteSamplers(1, &raw_sampler_);
    if (texture_) glDeleteTextures(1, &texture_);
}

void ShadowMap::begin_pass(int used_size) const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    // The whole texture is cleared (glClear ignores the viewport): lookups that stray outside the
    // used corner must read "far", not an older, larger frame's depths.
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glViewport(0, 0, used_size, used_size);
}

glm::mat4 ShadowMap::lookup_matrix(const LightFrame& light) const {
    // Light clip space [-1, 1] -> the used corner [0, used/size] of the texture, depth -> [0, 1].
    const float corner = float(light.map_size) / float(size_);
    glm::mat4 m(1.0f);
    m[0][0] = m[1][1] = 0.5f * corner;
    m[2][2] = 0.5f;
    m[3] = glm::vec4(0.5f * corner, 0.5f * corner, 0.5f, 1.0f);
    return m * light.view_proj;
}

void ShadowMap::bind_raw_depths(GLuint unit) const {
    bind_texture(GL_TEXTURE0 + unit);
    glBindSampler(unit, raw_sampler_);
}

void ShadowMap::bind_texture(GLenum unit) const {
    glActiveTexture(unit);
    glBindTexture(GL_TEXTURE_2D, texture_);
}

} // namespace tumble::render
