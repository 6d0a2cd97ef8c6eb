#include "render/occlusion_decals.h"

#include <GL/glext.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>

namespace tumble::render {

OcclusionDecals::OcclusionDecals()
    : program_(shader_asset("ao_decal.vert"), shader_asset("ao_decal.frag")),
      view_proj_(program_.uniform("u_view_proj")), camera_pos_(program_.uniform("u_camera_pos")) {
    glGenBuffers(1, &vbo_);
}

OcclusionDecals::~OcclusionDecals() {
    if (vbo_) glDeleteBuffers(1, &vbo_);
}

void OcclusionDecals::draw(const std::vector<Decal>& decals, const GpuMesh& square,
                           const glm::mat4& view_proj, glm::vec3 camera_pos) {
    if (decals.empty()) return;
    const std::size_t bytes = decals.size() * sizeof(Decal);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    if (bytes > capacity_) {
        capacity_ = std::max(bytes, 2 * capacity_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacity_), nullptr, GL_STREAM_DRAW);
    }
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(bytes), decals.data());

    glUseProgram(program_.id());
    glUniformMatrix4fv(view_proj_, 1, GL_FALSE, glm::value_ptr(view_proj));
    glUniform3fv(camera_pos_, 1, glm::value_ptr(camera_pos));
    // On the ground, in front of it by a hair (the polygon offset), behind anything standing on
    // it; multiplied into what is there; writing no depth.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -4.0f);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);

    square.bind();
    const auto stride = GLsizei(sizeof(Decal));
    auto attribute = [&](GLuint location, std::size_t offset) {
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location, 4, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offset));
        glVertexAttribDivisor(location, 1);
    };
    for (GLuint c = 0; c < 4; ++c) attribute(2 + c, offsetof(Decal, model) + c * sizeof(glm::vec4));
    for (GLuint k = 0; k < 3; ++k)
        attribute(6 + k, offsetof(Decal, occluder) + k * sizeof(glm::vec4));
    for (GLuint k = 9; k < 14; ++k) glDisableVertexAttribArray(k); // lit.vert's, not read here
    square.draw_instanced(GLsizei(decals.size()));
    glBindVertexArray(0);

    glDisable(GL_BLEND);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

} // namespace tumble::render
