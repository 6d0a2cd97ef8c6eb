#include "render/batches.h"

#include "render/ambient_occlusion.h"
#include "render/color.h"

#include <GL/glext.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>

namespace tumble::render {

float shininess_from_roughness(float roughness) {
    return std::exp2(10.0f * (1.0f - std::clamp(roughness, 0.0f, 1.0f))) + 1.0f;
}

InstanceData make_instance_data(const glm::mat4& model, glm::vec3 color, const Material& material,
                                bool checker) {
    InstanceData d{model,
                   glm::vec4(srgb_to_linear(color), checker ? 1.0f : 0.0f),
                   glm::vec4(shininess_from_roughness(material.roughness),
                             std::clamp(material.specular, 0.0f, 1.0f),
                             std::clamp(material.metallic, 0.0f, 1.0f),
                             1.0f - std::clamp(material.roughness, 0.0f, 1.0f)),
                   {}};
    const PackedOccluder none = no_occluder();
    for (std::size_t k = 0; k < 6; ++k) d.occluders[k] = none[k % 3];
    return d;
}

// --- BatchList -------------------------------------------------------------------------------
void BatchList::clear() {
    for (std::size_t i = 0; i < used_; ++i) {
        groups_[i].items.clear();
        groups_[i].distances.clear();
    }
    used_ = 0;
    batches_.clear();
    data_.clear();
}

void BatchList::add(const GpuMesh* mesh, bool cull_back, int rank, const InstanceData& instance,
                    float distance) {
    Group* group = nullptr;
    for (std::size_t i = 0; i < used_ && !group; ++i)
        if (groups_[i].mesh == mesh && groups_[i].cull_back == cull_back) group = &groups_[i];
    if (!group) {
        if (used_ == groups_.size()) groups_.push_back({});
        group = &groups_[used_++];
        group->mesh = mesh;
        group->cull_back = cull_back;
        group->rank = rank;
    }
    group->items.push_back(instance);
    group->distances.push_back(distance);
}

void BatchList::finish() {
    order_.resize(used_);
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    std::stable_sort(order_.begin(), order_.end(), [this](std::size_t a, std::size_t b) {
        return groups_[a].rank < groups_[b].rank;
    });
    batches_.clear();
    data_.clear();
    for (std::size_t i : order_) {
        Group& g = groups_[i];
        batches_.push_back({g.mesh, g.cull_back, std::uint32_t(data_.size()),
                            std::uint32_t(g.items.size()), g.rank});
        g.order.resize(g.items.size());
        std::iota(g.order.begin(), g.order.end(), 0u);
        std::stable_sort(g.order.begin(), g.order.end(), [&g](std::uint32_t a, std::uint32_t b) {
            return g.distances[a] < g.distances[b];
        });
        for (std::uint32_t k : g.order) data_.push_back(g.items[k]);
    }
}

std::uint64_t BatchList::triangles() const {
    std::uint64_t n = 0;
    for (const Batch& b : batches_) n += std::uint64_t(b.mesh->index_count() / 3) * b.count;
    return n;
}

// --- InstanceBuffer --------------------------------------------------------------------------
InstanceBuffer::InstanceBuffer() {
    glGenBuffers(1, &vbo_);
}

InstanceBuffer::~InstanceBuffer() {
    if (vbo_) glDeleteBuffers(1, &vbo_);
}

void InstanceBuffer::upload(const BatchList& list) {
    const std::size_t bytes = list.data().size() * sizeof(InstanceData);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    if (bytes > capacity_) {
        capacity_ = std::max(bytes, 2 * capacity_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacity_), nullptr, GL_STREAM_DRAW);
    }
    if (bytes > 0) glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(bytes), list.data().data());
}

namespace {

// Points attributes 2..13 of the bound vertex array at the instances from `first` on.
void point_instance_attributes(std::size_t first) {
    const auto stride = GLsizei(sizeof(InstanceData));
    const std::size_t base = first * sizeof(InstanceData);
    auto attribute = [&](GLuint location, GLint size, std::size_t offset) {
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(base + offset));
        glVertexAttribDivisor(location, 1);
    };
    for (GLuint c = 0; c < 4; ++c)
        attribute(2 + c, 4, offsetof(InstanceData, model) + c * sizeof(glm::vec4));
    attribute(6, 4, offsetof(InstanceData, color));
    attribute(7, 4, offsetof(InstanceData, material));
    for (GLuint k = 0; k < 6; ++k)
        attribute(8 + k, 4, offsetof(InstanceData, occluders) + k * sizeof(glm::vec4));
}

} // namespace

void InstanceBuffer::draw(const BatchList& list, GLenum cull_face, Select select, int rank) const {
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glCullFace(cull_face);
    for (const Batch& b : list.batches()) {
        if ((select == Select::Rank && b.rank != rank) ||
            (select == Select::ExceptRank && b.rank == rank))
            continue;
        if (b.cull_back)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        b.mesh->bind();
        point_instance_attributes(b.first);
        b.mesh->draw_instanced(GLsizei(b.count));
    }
    glBindVertexArray(0);
}

// --- Culling and level of detail -------------------------------------------------------------
Frustum Frustum::from_view_proj(const glm::mat4& m) {
    const glm::vec4 r0 = glm::row(m, 0), r1 = glm::row(m, 1), r2 = glm::row(m, 2),
                    r3 = glm::row(m, 3);
    Frustum f{{r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2}};
    for (glm::vec4& p : f.planes) p /= glm::length(glm::vec3(p));
    return f;
}

bool Frustum::intersects_sphere(glm::vec3 c, float r) const {
    for (const glm::vec4& p : planes)
        if (glm::dot(glm::vec3(p), c) + p.w < -r) return false;
    return true;
}

bool Frustum::intersects_swept_sphere(glm::vec3 c, float r, glm::vec3 d) const {
    // Outside a plane and moving away from (or along) it: the whole sweep stays outside.
    for (const glm::vec4& p : planes)
        if (glm::dot(glm::vec3(p), c) + p.w < -r && glm::dot(glm::vec3(p), d) <= 0.0f) return false;
    return true;
}

Frustum Frustum::cut_at(glm::vec3 eye, float distance) const {
    // planes[4] is the near plane, row 3 + row 2 of the view-projection matrix. For a perspective
    // projection both rows weigh only eye-space z, so its unit normal n is the camera's forward
    // direction (in world space: the view's rotation keeps lengths). The points at most
    // `distance` ahead of the eye, dot(n, x - eye) <= distance, are the inside of the plane
    // (-n, dot(n, eye) + distance).
    Frustum f = *this;
    const glm::vec3 forward(planes[4]);
    f.planes[5] = glm::vec4(-forward, glm::dot(forward, eye) + distance);
    return f;
}

int segments_for(float radius_px, float max_error_px, float max_edge_px) {
    if (!(radius_px > max_error_px)) return 3;
    const float half_angle = std::acos(1.0f - max_error_px / radius_px);
    const float by_error = std::ceil(glm::pi<float>() / half_angle);
    const float by_edge = std::ceil(glm::two_pi<float>() * radius_px / max_edge_px);
    return int(std::max(by_error, by_edge));
}

std::size_t choose_level(std::span<const int> levels, float radius_px, float max_error_px,
                         float max_edge_px) {
    const int needed = segments_for(radius_px, max_error_px, max_edge_px);
    for (std::size_t i = 0; i < levels.size(); ++i)
        if (levels[i] >= needed) return i;
    return levels.size() - 1;
}

float projected_radius_px(float radius, float distance, float fov_y_deg, int height_px) {
    const float d = std::max(distance, radius);
    const float half_height = std::tan(glm::radians(fov_y_deg) * 0.5f);
    return radius * 0.5f * float(height_px) / (d * half_height);
}

} // namespace tumble::render
