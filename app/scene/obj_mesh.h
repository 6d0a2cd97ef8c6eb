#pragma once
// Triangle meshes of `{"type": "mesh", "file": ...}` bodies, read from Wavefront OBJ files with
// tinyobjloader (Debian's libtinyobjloader-dev, double precision). Only the vertex positions
// ("v") and faces ("f", polygons split into triangles) are used; normals, texture coordinates,
// groups and materials are ignored. check_obj_lines() (obj_lines.h) judges the "v" and "f" lines
// first: tinyobjloader reads what it cannot parse as 0. A file is found next to the scene file
// first, then among the meshes bundled from assets/meshes/ (embedded in the binary, so built-in
// scenes need no files on disk).
#include "physics/mesh.h"
#include "render/mesh_data.h"

#include <memory>
#include <optional>
#include <string>

namespace tumble::app {

struct ObjMesh {
    std::shared_ptr<const physics::TriangleMesh> solid; // body frame, m (for physics)
    std::shared_ptr<const render::MeshData> drawn;      // the same triangles, flat shaded
    std::string origin;                                 // path read, or "builtin:<name>"
};

// Parses OBJ text into triangles scaled by `scale`. Returns the reason when the text holds no
// usable triangles (tinyobjloader's error, or no faces); check_closed_mesh() judges the rest.
std::optional<std::string> parse_obj(const std::string& text, double scale,
                                     physics::TriangleMesh& out);

// The OBJ text of `file` for a scene read from `scene_source` (a path, or "builtin:<name>"):
// `file` relative to the scene file's folder, else a bundled mesh of that file name. Empty
// optional when neither exists; `origin` says which was read.
std::optional<std::string> find_obj_text(const std::string& file, const std::string& scene_source,
                                         std::string& origin);

// The render mesh of a solid: flat shaded (each facet its own normal).
std::shared_ptr<const render::MeshData> drawn_mesh(const physics::TriangleMesh& solid);

} // namespace tumble::app
