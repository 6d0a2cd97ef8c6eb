#pragma once
// Translucent surfaces (SceneView::glass): the energy ellipsoid and the invariable plane of
// Poinsot's construction, seen through. Drawn after the opaque scene and the sky, lit simply
// (glass.frag: a soft diffuse term and a rim that outlines the shape), depth-tested so that
// bodies in front hide them, writing no depth so that they hide nothing. In two halves around the
// world's lines (renderer.cpp): first the far sides of closed meshes and the open ones (planes),
// then the near sides of closed meshes, so a curve drawn on a surface or inside it shows through
// the near side, tinted, and a curve behind it is tinted twice.
#include "render/draw_list.h"
#include "render/scene_view.h"
#include "render/shader.h"

#include <vector>

namespace tumble::render {

class GlassPass {
  public:
    GlassPass(); // needs a current GL context

    enum class Half { Far, Near };
    // Draws one half of `glass` into the bound framebuffer.
    void draw(const std::vector<Glass>& glass, Half half, const MeshLibrary& library,
              const glm::mat4& view_proj, const Camera& camera, const Light& light);

  private:
    ShaderProgram program_;
    GLint model_, view_proj_, camera_pos_, light_dir_, color_;
};

} // namespace tumble::render
