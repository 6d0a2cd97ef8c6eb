#pragma once
// The two matrices that take a world point to the screen (GLM, right-handed, OpenGL clip space):
//   view:       world -> eye space (camera at the origin looking down -z, `up` on screen up)
//   projection: eye space -> clip space (perspective; depth maps z_near..z_far to -1..1)
#include "render/scene_view.h"

#include <glm/glm.hpp>

namespace tumble::render {

glm::mat4 view_matrix(const Camera& camera);
glm::mat4 projection_matrix(const Camera& camera, float aspect); // aspect = width / height

} // namespace tumble::render
