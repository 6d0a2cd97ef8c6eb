#include "render/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace tumble::render {

glm::mat4 view_matrix(const Camera& camera) {
    const glm::vec3 forward = camera.target - camera.position;
    glm::vec3 up = camera.up;
    // lookAt builds the camera's right axis as forward x up; looking straight along `up` (say,
    // straight down on a z-up world) makes that zero and the matrix NaN. Pick another up then.
    const float sine = glm::length(glm::cross(glm::normalize(forward), glm::normalize(up)));
    if (!(sine > 1e-4f))
        up = std::abs(forward.y) < std::abs(forward.x) ? glm::vec3{0, 1, 0} : glm::vec3{1, 0, 0};
    return glm::lookAt(camera.position, camera.target, up);
}

glm::mat4 projection_matrix(const Camera& camera, float aspect) {
    return glm::perspective(glm::radians(camera.fov_y_deg), aspect, camera.z_near, camera.z_far);
}

} // namespace tumble::render
