#include "render/ambient_occlusion.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tumble::render {

PackedOccluder pack(const Occluder& o) {
    PackedOccluder rows;
    for (int i = 0; i < 3; ++i) {
        // glm is column-major: row i of A is (A[0][i], A[1][i], A[2][i]).
        rows[std::size_t(i)] =
            glm::vec4(o.to_unit[0][i], o.to_unit[1][i], o.to_unit[2][i], o.centre[i]);
    }
    return rows;
}

PackedOccluder no_occluder() {
    Occluder far;
    far.centre = glm::vec3(1000.0f, 1000.0f, 1000.0f);
    return pack(far);
}

Occluder occluder_of(MeshKind kind, const glm::mat4& t, glm::vec3 unit_half_extent) {
    // Semi-axes of the ellipsoid in the unit mesh's frame, then the instance's transform on top.
    glm::vec3 semi(1.0f);
    switch (kind) {
    case MeshKind::Sphere:
        break;
    case MeshKind::Box:
        semi = glm::vec3(kBoxToEllipsoid);
        break;
    case MeshKind::Cylinder:
        semi = glm::vec3(kCylinderAcross, kCylinderAcross, kCylinderAlong);
        break;
    case MeshKind::Custom:
        semi = kBoxToEllipsoid * glm::max(unit_half_extent, glm::vec3(1e-6f));
        break;
    case MeshKind::Plane:
        semi = glm::vec3(0.0f);
        break;
    }
    // Unit sphere -> world: M = T3 diag(semi); A = M^-1.
    glm::mat3 m(t);
    for (int k = 0; k < 3; ++k) m[k] *= semi[k];
    Occluder o;
    o.centre = glm::vec3(t[3]);
    o.to_unit = glm::inverse(m);
    o.bound = std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
    return o;
}

void nearest_occluders(std::span<const Occluder> occ, std::span<const Receiver> rec,
                       std::vector<std::array<std::int32_t, 2>>& out,
                       std::vector<std::int32_t>& order) {
    out.assign(rec.size(), {-1, -1});
    if (occ.empty()) return;
    // Occluders sorted by the left end of their reach along x; a receiver scans those whose
    // interval can overlap its own.
    order.resize(occ.size());
    std::iota(order.begin(), order.end(), 0);
    auto left = [&](std::int32_t i) {
        return occ[std::size_t(i)].centre.x - kOcclusionReach * occ[std::size_t(i)].bound;
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::int32_t a, std::int32_t b) { return left(a) < left(b); });
    float widest = 0.0f;
    for (const Occluder& o : occ) widest = std::max(widest, kOcclusionReach * o.bound);

    for (std::size_t r = 0; r < rec.size(); ++r) {
        const Receiver& R = rec[r];
        // First occluder whose left end could still reach R: left >= R.x - R.bound - 2 widest.
        const float from = R.centre.x - R.bound - 2.0f * widest;
        auto it = std::lower_bound(order.begin(), order.end(), from,
                                   [&](std::int32_t i, float x) { return left(i) < x; });
        float best[2] = {1e30f, 1e30f};
        std::int32_t pick[2] = {-1, -1};
        for (; it != order.end() && left(*it) <= R.centre.x + R.bound; ++it) {
            const Occluder& o = occ[std::size_t(*it)];
            if (o.body == R.body) continue;
            // Gap between the receiver's bounding sphere and the occluder's reach.
            const float gap =
                glm::length(R.centre - o.centre) - R.bound - kOcclusionReach * o.bound;
            if (gap >= 0.0f) continue;
            // Rank by how deep the receiver sits in the reach, relative to its size: the
            // occluder that darkens it most first.
            const float depth = gap / (kOcclusionReach * o.bound);
            const bool first = depth < best[0] || (depth == best[0] && *it < pick[0]);
            if (first) {
                best[1] = best[0], pick[1] = pick[0];
                best[0] = depth, pick[0] = *it;
            } else if (depth < best[1] || (depth == best[1] && *it < pick[1])) {
                best[1] = depth, pick[1] = *it;
            }
        }
        out[r] = {pick[0], pick[1]};
    }
}

void add_ground_decals(const glm::mat4& plane, std::span<const Occluder> occluders,
                       std::vector<Decal>& out) {
    const glm::vec3 origin(plane[3]);
    const glm::vec3 ex(plane[0]), ey(plane[1]); // the square's half sides
    const float hx = glm::length(ex), hy = glm::length(ey);
    if (hx <= 0.0f || hy <= 0.0f) return;
    const glm::vec3 u = ex / hx, v = ey / hy;
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    for (const Occluder& o : occluders) {
        const float reach = kOcclusionReach * o.bound;
        const glm::vec3 rel = o.centre - origin;
        const float height = glm::dot(rel, n);
        if (height <= -o.bound || height >= reach) continue; // under the plane, or too high
        const float x = glm::dot(rel, u), y = glm::dot(rel, v);
        if (std::abs(x) >= hx + reach || std::abs(y) >= hy + reach) continue; // off the square
        // The square on the plane that the reach sphere cuts, whose half side is the cut
        // circle's radius.
        const float half = std::sqrt(std::max(reach * reach - height * height, 0.0f));
        glm::mat4 m(1.0f);
        m[0] = glm::vec4(u * half, 0.0f);
        m[1] = glm::vec4(v * half, 0.0f);
        m[2] = glm::vec4(n, 0.0f);
        m[3] = glm::vec4(origin + x * u + y * v, 1.0f);
        out.push_back({m, pack(o)});
    }
}

} // namespace tumble::render
