#include "physics/hull.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace tumble::physics {
namespace {

// Planes, edges and bounds from vertices + face loops. A directed edge (a, b) of face f has its
// reverse (b, a) in the neighbouring face g: store it once, as {a, b, left = f, right = g}.
void finish_hull(ConvexHull& h) {
    std::map<std::pair<int, int>, int> owner; // directed edge -> face
    for (int f = 0; f < static_cast<int>(h.faces.size()); ++f) {
        HullFace& face = h.faces[f];
        // Newell's method, a robust normal for a planar polygon: sum of p_k x p_k+1.
        Vec3 n = Vec3::Zero(), c = Vec3::Zero();
        for (int k = 0; k < face.count; ++k) {
            const Vec3& p = h.vertices[h.face_vertices[face.first + k]];
            const Vec3& q = h.vertices[h.face_vertices[face.first + (k + 1) % face.count]];
            n += p.cross(q); // sum of p_k x p_k+1 = twice the outward area vector
            c += p;
            owner[{h.face_vertices[face.first + k],
                   h.face_vertices[face.first + (k + 1) % face.count]}] = f;
        }
        face.normal = n.normalized();
        c /= face.count;
        face.offset = face.normal.dot(c);
    }
    h.edges.clear();
    for (const auto& [e, f] : owner)
        if (e.first < e.second)
            h.edges.push_back({e.first, e.second, f, owner.at({e.second, e.first})});
    h.centroid = std::accumulate(h.vertices.begin(), h.vertices.end(), Vec3(Vec3::Zero())) /
                 static_cast<double>(h.vertices.size());
    h.box_min = h.box_max = h.vertices[0];
    h.radius = 0.0;
    for (const Vec3& v : h.vertices) {
        h.box_min = h.box_min.cwiseMin(v);
        h.box_max = h.box_max.cwiseMax(v);
        h.radius = std::max(h.radius, v.norm());
    }
}

} // namespace

ConvexHull make_box_hull(const Vec3& e) {
    ConvexHull h;
    // Vertex k has coordinates (+-ex, +-ey, +-ez) with the signs from bits 0, 1, 2 of k.
    for (int k = 0; k < 8; ++k)
        h.vertices.emplace_back(k & 1 ? e.x() : -e.x(), k & 2 ? e.y() : -e.y(),
                                k & 4 ? e.z() : -e.z());
    // Loops counter-clockwise seen from outside: +x, -x, +y, -y, +z, -z.
    const int loops[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                             {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    for (const auto& loop : loops) {
        h.faces.push_back({Vec3::Zero(), 0.0, static_cast<int>(h.face_vertices.size()), 4});
        h.face_vertices.insert(h.face_vertices.end(), loop, loop + 4);
    }
    finish_hull(h);
    return h;
}

std::optional<std::string> make_mesh_hull(const TriangleMesh& mesh, ConvexHull& out) {
    const int nt = static_cast<int>(mesh.triangles.size());
    Vec3 lo = mesh.vertices[0], hi = lo;
    for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const double tol = 1e-6 * (hi - lo).norm();

    // Convexity: every vertex on or behind every triangle's plane.
    std::vector<Vec3> normal(nt);
    std::vector<double> offset(nt);
    for (int t = 0; t < nt; ++t) {
        const auto& tri = mesh.triangles[t];
        const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]],
                   &c = mesh.vertices[tri[2]];
        normal[t] = (b - a).cross(c - a).normalized();
        offset[t] = normal[t].dot(a);
        for (int v = 0; v < static_cast<int>(mesh.vertices.size()); ++v) {
            const double d = normal[t].dot(mesh.vertices[v]) - offset[t];
            if (d > tol)
                return "mesh is not convex: vertex " + std::to_string(v) + " lies " +
                       std::to_string(d) + " m outside the plane of triangle " + std::to_string(t) +
                       "; contacts treat a mesh as the convex polyhedron it must bound";
        }
    }

    // Merge coplanar neighbours: union-find over triangles sharing an edge in the same plane.
    std::vector<int> parent(nt);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::map<std::pair<int, int>, int> edge_tri; // directed edge -> triangle
    for (int t = 0; t < nt; ++t)
        for (int j = 0; j < 3; ++j)
            edge_tri[{mesh.triangles[t][j], mesh.triangles[t][(j + 1) % 3]}] = t;
    for (const auto& [e, t] : edge_tri) {
        const int u = edge_tri.at({e.second, e.first});
        if (normal[t].dot(normal[u]) > 1.0 - 1e-9 && std::abs(offset[t] - offset[u]) <= tol)
            parent[find(t)] = find(u);
    }

    // Each group's boundary (directed edges whose reverse lies in another group) is one convex
    // loop; follow it vertex to vertex and drop vertices where it runs straight on.
    out = ConvexHull();
    out.vertices = mesh.vertices;
    std::map<int, std::map<int, int>> next; // group -> (from vertex -> to vertex)
    for (const auto& [e, t] : edge_tri)
        if (find(t) != find(edge_tri.at({e.second, e.first}))) next[find(t)][e.first] = e.second;
    for (const auto& [group, links] : next) {
        std::vector<int> loop;
        int v = links.begin()->first;
        do {
            loop.push_back(v);
            v = links.at(v);
        } while (v != loop.front() && loop.size() <= links.size());
        std::vector<int> corners;
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const Vec3& p = mesh.vertices[loop[(k + loop.size() - 1) % loop.size()]];
            const Vec3& q = mesh.vertices[loop[k]];
            const Vec3& r = mesh.vertices[loop[(k + 1) % loop.size()]];
            if ((q - p).cross(r - q).norm() > tol * (r - p).norm()) corners.push_back(loop[k]);
        }
        out.faces.push_back({normal[group], offset[group],
                             static_cast<int>(out.face_vertices.size()),
                             static_cast<int>(corners.size())});
        out.face_vertices.insert(out.face_vertices.end(), corners.begin(), corners.end());
    }
    // Keep only vertices that are corners of some face (mid-edge vertices add nothing).
    std::vector<int> remap(mesh.vertices.size(), -1);
    std::vector<Vec3> used;
    for (int& v : out.face_vertices) {
        if (remap[v] < 0)
            remap[v] = static_cast<int>(used.size()), used.push_back(mesh.vertices[v]);
        v = remap[v];
    }
    out.vertices = std::move(used);
    finish_hull(out);
    return std::nullopt;
}

} // namespace tumble::physics
