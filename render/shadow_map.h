#pragma once
// Shadows from the key light (a directional light): the classic two-pass shadow map.
//   1. From the light, draw the shadow casters' depth into a depth texture (orthographic: the
//      light's rays are parallel).
//   2. When shading a point, look it up in that texture: if something nearer the light covered
//      it, the point is in shadow. lit.frag compares with a sampler2DShadow and linear filtering
//      (each lookup is a 2x2 percentage-closer filter) at four positions a texel apart, which
//      gives a soft edge about two texels wide (percentage-closer filtering, Reeves et al. 1987).
//      The map's resolution is chosen per frame so that a texel is about 1.2 cm (fit_light_frame):
//      llvmpipe pays about 2 ms per 720p frame for every shadow lookup per pixel, so few
//      lookups on a map of the right size beat many on a fine one.
//
// Acne (a surface shadowing itself in stripes) is avoided by drawing only the casters' back
// faces into the map (the lit front faces then compare against a surface a body's thickness
// behind them), plus a slope-scaled depth offset and a normal offset of about a texel for the
// two-sided OBJ meshes. The ground casts no shadow, so it never shadows itself. Peter-panning
// (shadows detached from their casters) stays below a texel because the offsets are that small.
//
// The light's frustum is fitted each frame around the casters the camera can see the shadows of,
// and stabilised so that shadows do not shimmer as bodies move: its size changes only in steps
// of 2^(1/4), and its centre moves in whole texels.
#include <GL/gl.h>
#include <glm/glm.hpp>

#include <span>

namespace tumble::render {

struct LightFrame {
    glm::mat4 view_proj{1.0f}; // world -> light clip space (x, y, z in [-1, 1] inside)
    float texel_size = 0.0f;   // one shadow-map texel, metres
    float depth_range = 0.0f;  // metres along the light from map depth 0 to depth 1
    int map_size = 0;          // texels per side actually used (a corner of the texture)
    bool empty = true;         // no casters: nothing to draw, nothing in shadow
};

// Fits the light's orthographic frustum around `casters` (xyz: centre, w: radius, world), for a
// light travelling along `direction`. The map uses the smallest power-of-two size (up to
// `max_map_size`) whose texels are no larger than `texel_target` metres: shadows are filtered
// over about a texel, so this sets how soft their edges are, and a small scene costs a small
// map. The frustum's half width is at most `max_half_size` metres.
LightFrame fit_light_frame(glm::vec3 direction, std::span<const glm::vec4> casters,
                           int max_map_size, float texel_target = 0.012f,
                           float max_half_size = 40.0f);

// The depth texture and the framebuffer that renders into it. Needs a current GL context.
class ShadowMap {
  public:
    explicit ShadowMap(int size);
    ~ShadowMap();
    ShadowMap(const ShadowMap&) = delete;
    ShadowMap& operator=(const ShadowMap&) = delete;

    // Binds the framebuffer, clears the whole map to "far" and sets the viewport to the corner of
    // `used_size` texels this frame draws into.
    void begin_pass(int used_size) const;
    void bind_texture(GLenum unit) const;
    // Binds the same texture to texture unit `unit` (0, 1, ...) through a sampler that reads raw
    // depths, nearest texel, no comparison: the soft shadows' blocker search (lit.frag).
    void bind_raw_depths(GLuint unit) const;
    // World -> texture coordinates (xy, in the used corner) and reference depth (z) in [0, 1].
    glm::mat4 lookup_matrix(const LightFrame& light) const;
    int size() const { return size_; }

  private:
    int size_ = 0;
    GLuint texture_ = 0, fbo_ = 0, raw_sampler_ = 0;
};

} // namespace tumble::render
