#pragma once
// Shadows from the key light (a directional light): the classic two-pass shadow map.
//   1. From the light, draw the shadow casters' depth into a depth texture (orthographic: the
//      light's rays are parallel).
//   2. When shading a point, look it up in that texture: if something nearer the light covered
//      it, the point is in shadow. lit.frag compares with a sampler2DShadow and linear filtering
//      (each lookup is a 2x2 percentage-closer filter) at several nearby positions, which gives a
//      soft edge of a fixed width in metres (percentage-closer filtering, Reeves et al. 1987).
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
    bool empty = true;         // no casters: nothing to draw, nothing in shadow
};

// Fits the light's orthographic frustum around `casters` (xyz: centre, w: radius, world), for a
// light travelling along `direction`, on a square map of `map_size` texels. The frustum's half
// width is at most `max_half_size` metres around the casters' centre of bounds.
LightFrame fit_light_frame(glm::vec3 direction, std::span<const glm::vec4> casters, int map_size,
                           float max_half_size = 40.0f);

// The depth texture and the framebuffer that renders into it. Needs a current GL context.
class ShadowMap {
  public:
    explicit ShadowMap(int size);
    ~ShadowMap();
    ShadowMap(const ShadowMap&) = delete;
    ShadowMap& operator=(const ShadowMap&) = delete;

    // Binds the framebuffer with the viewport on the whole map and clears it to "far".
    void begin_pass() const;
    void bind_texture(GLenum unit) const;
    int size() const { return size_; }

  private:
    int size_ = 0;
    GLuint texture_ = 0, fbo_ = 0;
};

} // namespace tumble::render
