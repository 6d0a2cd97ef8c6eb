#include "render/glass.h"

#include "render/color.h"

#include <GL/glext.h>
#include <glm/gtc/type_ptr.hpp>

namespace tumble::render {
namespace {

// The unit mesh of a glass shape: the finest sphere (a big smooth surface, seen up close), the
// box, the plane or the finest cylinder.
const GpuMesh& mesh_of(MeshKind kind, const MeshLibrary& library) {
    switch (kind) {
    case MeshKind::Box:
        return library.box;
    case MeshKind::Plane:
        return library.plane;
    case MeshKind::Cylinder:
        return library.cylinders.back();
    case MeshKind::Sphere:
    case MeshKind::Custom: // not drawn as glass (scene_view.h); a sphere stands in
        break;
    }
    return library.spheres.back();
}

} // namespace

GlassPass::GlassPass()
    : program_(shader_asset("glass.vert"), shader_asset("glass.frag")),
      model_(program_.uniform("u_model")), view_proj_(program_.uniform("u_view_proj")),
      camera_pos_(program_.uniform("u_camera_pos")), light_dir_(program_.uniform("u_light_dir")),
      color_(program_.uniform("u_color")) {}

void GlassPass::draw(const std::vector<Glass>& glass, Half half, const MeshLibrary& library,
                     const glm::mat4& view_proj, const Camera& camera, const Light& light) {
    if (glass.empty()) return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(program_.id());
    glUniformMatrix4fv(view_proj_, 1, GL_FALSE, glm::value_ptr(view_proj));
    glUniform3fv(camera_pos_, 1, glm::value_ptr(camera.position));
    const float length = glm::length(light.direction);
    const glm::vec3 dir = length > 0.0f ? light.direction / length : glm::vec3(0, 0, -1);
    glUniform3fv(light_dir_, 1, glm::value_ptr(dir));
    for (const Glass& g : glass) {
        const bool open = g.mesh == MeshKind::Plane;
        if (open && half == Half::Near) continue; // an open surface: once, in the far half
        if (open) {
            glDisable(GL_CULL_FACE);
        } else { // far half: the faces turned away (cull the front ones); near half: the others
            glEnable(GL_CULL_FACE);
            glCullFace(half == Half::Far ? GL_FRONT : GL_BACK);
        }
        glUniformMatrix4fv(model_, 1, GL_FALSE, glm::value_ptr(g.transform));
        const glm::vec3 linear = srgb_to_linear(glm::vec3(g.rgba));
        glUniform4f(color_, linear.r, linear.g, linear.b, g.rgba.a);
        const GpuMesh& mesh = mesh_of(g.mesh, library);
        mesh.bind();
        mesh.draw();
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

} // namespace tumble::render
