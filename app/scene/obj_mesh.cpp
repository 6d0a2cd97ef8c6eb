#include "app/scene/obj_mesh.h"

#include "app/scene/input_file.h"

#include "app/scene/assets.h"

#include <tiny_obj_loader.h>

#include <filesystem>

namespace tumble::app {

std::optional<std::string> parse_obj(const std::string& text, double scale,
                                     physics::TriangleMesh& out) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config))
        return "not a readable OBJ file: " +
               (reader.Error().empty() ? std::string("no vertices") : reader.Error());
    const std::vector<tinyobj::real_t>& v = reader.GetAttrib().vertices;
    out.vertices.clear();
    out.triangles.clear();
    for (std::size_t i = 0; i + 2 < v.size(); i += 3)
        out.vertices.emplace_back(scale * double(v[i]), scale * double(v[i + 1]),
                                  scale * double(v[i + 2]));
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t i = 0; i + 2 < idx.size(); i += 3)
            out.triangles.push_back(
                {idx[i].vertex_index, idx[i + 1].vertex_index, idx[i + 2].vertex_index});
    }
    if (out.triangles.empty()) return std::string("the OBJ file has no faces (\"f\" lines)");
    return std::nullopt;
}

std::optional<std::string> find_obj_text(const std::string& file, const std::string& scene_source,
                                         std::string& origin) {
    namespace fs = std::filesystem;
    if (!scene_source.starts_with("builtin:")) {
        const fs::path path = fs::path(scene_source).parent_path() / file;
        std::error_code ec;
        if (fs::exists(path, ec)) { // a FIFO or device too: read_input_file says what is wrong
            origin = path.string();
            return read_input_file(path, "OBJ mesh");
        }
    }
    if (file.find('/') != std::string::npos) return std::nullopt;
    const std::string_view bundled = assets::find(file);
    if (bundled.empty() || !file.ends_with(".obj")) return std::nullopt;
    origin = "builtin:" + file;
    return std::string(bundled);
}

std::shared_ptr<const render::MeshData> drawn_mesh(const physics::TriangleMesh& solid) {
    std::vector<glm::vec3> positions;
    positions.reserve(solid.vertices.size());
    for (const physics::Vec3& p : solid.vertices)
        positions.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    std::vector<std::uint32_t> indices;
    indices.reserve(3 * solid.triangles.size());
    for (const auto& t : solid.triangles)
        for (int k : t) indices.push_back(std::uint32_t(k));
    return std::make_shared<const render::MeshData>(render::flat_shaded_mesh(positions, indices));
}

} // namespace tumble::app
