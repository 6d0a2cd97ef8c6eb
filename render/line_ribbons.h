#pragma once
// World-space polylines (SceneView::lines: trails, the curves of Poinsot's construction) drawn
// as ribbons a fixed number of pixels wide. Core-profile GL has no wide lines, so each segment
// becomes a quad on the CPU: both ends go to clip space, and each is pushed sideways by half the
// width, perpendicular to the segment as it appears on screen, in units of clip w so the width
// stays in pixels at any depth. Depth is kept: bodies hide the lines behind them. Segments with
// an end behind the camera are skipped (their projection would wrap around).
#include "render/scene_view.h"
#include "render/shader.h"
#include "render/vertex_stream.h"

#include <GL/gl.h>
#include <glm/glm.hpp>

#include <vector>

namespace tumble::render {

class LineRibbons {
  public:
    LineRibbons(); // needs a current GL context

    // Draws `lines` into the bound framebuffer, blended, depth-tested, writing no depth.
    void draw(const Polylines& lines, const glm::mat4& view_proj, int width, int height);

  private:
    ShaderProgram program_;
    VertexStream stream_{4, 4};   // clip x, y, z, w; r, g, b, a (linear)
    std::vector<float> vertices_; // this frame's, 8 floats per vertex
};

} // namespace tumble::render
