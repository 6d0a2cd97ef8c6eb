#pragma once
// The GL side of the ground's ambient occlusion (ambient_occlusion.h): the decals of one frame
// drawn over the ground already in the target, each multiplying the colour under it by how much
// sky its body leaves (ao_decal.vert / .frag). Drawn after the scene and before the sky, with the
// depth test on and no depth writes: a body in front of a decal hides it, and where no ground
// was drawn the sky pass paints over it.
#include "render/ambient_occlusion.h"
#include "render/mesh.h"
#include "render/shader.h"

#include <GL/gl.h>
#include <glm/glm.hpp>

#include <vector>

namespace tumble::render {

class OcclusionDecals {
  public:
    OcclusionDecals(); // needs a current GL context
    ~OcclusionDecals();
    OcclusionDecals(const OcclusionDecals&) = delete;
    OcclusionDecals& operator=(const OcclusionDecals&) = delete;

    // `square` is the plane mesh (the unit square [-1, 1]^2 at z = 0).
    void draw(const std::vector<Decal>& decals, const GpuMesh& square, const glm::mat4& view_proj,
              glm::vec3 camera_pos);

  private:
    ShaderProgram program_;
    GLint view_proj_, camera_pos_;
    GLuint vbo_ = 0;
    std::size_t capacity_ = 0; // bytes
};

} // namespace tumble::render
