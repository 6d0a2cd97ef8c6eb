#include "render/line_ribbons.h"

#include "render/color.h"

#include <GL/glext.h>

#include <cmath>

namespace tumble::render {

LineRibbons::LineRibbons() : program_(shader_asset("line.vert"), shader_asset("line.frag")) {}

void LineRibbons::draw(const Polylines& lines, const glm::mat4& view_proj, int width, int height) {
    vertices_.clear();
    const glm::vec2 to_ndc(2.0f / float(width), 2.0f / float(height)); // pixels -> NDC
    for (const Polylines::Strip& s : lines.strips) {
        for (std::uint32_t i = s.first + 1; i < s.first + s.count; ++i) {
            const glm::vec4 a = view_proj * glm::vec4(lines.points[i - 1], 1.0f);
            const glm::vec4 b = view_proj * glm::vec4(lines.points[i], 1.0f);
            if (a.w <= 1e-4f || b.w <= 1e-4f) continue;
            // Direction on screen, in pixels; the offset perpendicular to it, half the width.
            const glm::vec2 d = (glm::vec2(b) / b.w - glm::vec2(a) / a.w) / to_ndc;
            const float length = glm::length(d);
            if (length <= 1e-6f) continue;
            const glm::vec2 across = glm::vec2(-d.y, d.x) / length * (0.5f * s.width_px) * to_ndc;
            const glm::vec4 ca =
                glm::vec4(srgb_to_linear(glm::vec3(lines.colors[i - 1])), lines.colors[i - 1].a);
            const glm::vec4 cb =
                glm::vec4(srgb_to_linear(glm::vec3(lines.colors[i])), lines.colors[i].a);
            const glm::vec4 corner[4] = {
                a - glm::vec4(across * a.w, 0, 0), b - glm::vec4(across * b.w, 0, 0),
                b + glm::vec4(across * b.w, 0, 0), a + glm::vec4(across * a.w, 0, 0)};
            const glm::vec4 colour[4] = {ca, cb, cb, ca};
            for (int k : {0, 1, 2, 0, 2, 3})
                vertices_.insert(vertices_.end(),
                                 {corner[k].x, corner[k].y, corner[k].z, corner[k].w, colour[k].r,
                                  colour[k].g, colour[k].b, colour[k].a});
        }
    }
    if (vertices_.empty()) return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(program_.id());
    stream_.draw_triangles(vertices_);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

} // namespace tumble::render
