#include "render/cone_mesh.h"

#include <cmath>
#include <stdexcept>

namespace tumble::render {

MeshData make_cone(int segments) {
    if (segments < 3) throw std::invalid_argument("a cone needs at least 3 segments");
    MeshData m;
    const float two_pi = 6.28318530717958647692f;
    const float slant = std::sqrt(0.5f); // side normal (cos a, sin a, 1) / sqrt(2)
    for (int i = 0; i < segments; ++i) {
        // Each side triangle gets its own apex vertex, with the normal halfway round, so the
        // shading of the side is smooth around and the apex is not a pinched average.
        const float a0 = two_pi * float(i) / float(segments);
        const float a1 = two_pi * float(i + 1) / float(segments);
        const float am = 0.5f * (a0 + a1);
        const auto base = std::uint32_t(m.vertices.size());
        m.vertices.push_back({{std::cos(a0), std::sin(a0), 0.0f},
                              slant * glm::vec3(std::cos(a0), std::sin(a0), 1.0f)});
        m.vertices.push_back({{std::cos(a1), std::sin(a1), 0.0f},
                              slant * glm::vec3(std::cos(a1), std::sin(a1), 1.0f)});
        m.vertices.push_back(
            {{0.0f, 0.0f, 1.0f}, slant * glm::vec3(std::cos(am), std::sin(am), 1.0f)});
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
    }
    // The base cap: a fan around its centre, wound clockwise seen from +z (its outside is -z).
    const auto centre = std::uint32_t(m.vertices.size());
    m.vertices.push_back({{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}});
    for (int i = 0; i < segments; ++i) {
        const float a = two_pi * float(i) / float(segments);
        m.vertices.push_back({{std::cos(a), std::sin(a), 0.0f}, {0.0f, 0.0f, -1.0f}});
    }
    for (int i = 0; i < segments; ++i) {
        const auto a = centre + 1 + std::uint32_t(i);
        const auto b = centre + 1 + std::uint32_t((i + 1) % segments);
        m.indices.insert(m.indices.end(), {centre, b, a});
    }
    return m;
}

} // namespace tumble::render
