#pragma once
// Rods and arrows drawn in the world (w and L arrows, the traced axis of a trail): the unit
// cylinder of render/scene_view.h (radius 1 around z, z in [-1, 1]) turned and stretched.
#include "render/scene_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace tumble::app {

// A rotation taking +z to the unit vector d.
inline glm::mat4 aim_z_at(const glm::vec3& d) {
    const glm::vec3 z(0.0f, 0.0f, 1.0f);
    const glm::vec3 axis = glm::cross(z, d);
    const float s = glm::length(axis), c = glm::dot(z, d);
    if (s < 1e-6f)
        return c > 0.0f ? glm::mat4(1.0f)
                        : glm::rotate(glm::mat4(1.0f), 3.14159265f, glm::vec3(1, 0, 0));
    return glm::rotate(glm::mat4(1.0f), std::atan2(s, c), axis / s);
}

// A cylinder of `radius` from `a` to `b` (not a body: it casts and receives no occlusion).
inline render::Instance rod(const glm::vec3& a, const glm::vec3& b, float radius,
                            const glm::vec3& color) {
    const glm::vec3 d = b - a;
    const float length = glm::length(d);
    render::Instance r;
    r.mesh = render::MeshKind::Cylinder;
    r.transform = glm::translate(glm::mat4(1.0f), 0.5f * (a + b)) *
                  aim_z_at(length > 0.0f ? d / length : glm::vec3(0, 0, 1)) *
                  glm::scale(glm::mat4(1.0f), glm::vec3(radius, radius, 0.5f * length));
    r.color = color;
    r.material = render::Material{0.35f, 0.5f, 0.0f};
    return r;
}

} // namespace tumble::app
