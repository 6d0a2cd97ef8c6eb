#pragma once
// Reads a body's "shape" object (docs/scene-format.md): sphere, box, plane, capsule or mesh.
// Mesh files are read once per (file, scale) for the whole scene and shared by the bodies that
// use them, in physics (the triangles) and in the picture (Scene::meshes).
#include "app/scene/content_hash.h"
#include "app/scene/json_reader.h"
#include "app/scene/obj_mesh.h"
#include "app/scene/scene.h"

#include <map>
#include <string>
#include <utility>

namespace tumble::app {

struct ShapeContext {
    std::string scene_source; // where mesh files are looked up (obj_mesh.h)
    std::vector<std::shared_ptr<const render::MeshData>>* drawn = nullptr; // Scene::meshes
    std::map<std::pair<std::string, double>, std::pair<ObjMesh, std::uint32_t>> loaded;
    ContentHash* inputs = nullptr; // each mesh file's text is added as it is read
};

// Fills body.shape (and body.mesh for a mesh) and the look's plane extent / mesh id.
void read_shape(JsonReader r, ShapeContext& context, physics::BodyDef& body, BodyLook& look);

// Volume of the body's solid, m^3 (a mesh's from its triangles).
double body_volume(const physics::BodyDef& body);

} // namespace tumble::app
