#pragma once
// A body's `material` in the scene file: a preset name or an object of the three knobs of
// render::Material (docs/scene-format.md). Presets:
//   plastic  roughness 0.45, specular 0.5   the default for solid bodies
//   glossy   roughness 0.15, specular 0.8   lacquer, polished stone
//   matte    roughness 0.9,  specular 0.1   the default for planes: paper, chalk, concrete
//   rubber   roughness 0.7,  specular 0.2
//   metal    roughness 0.2,  specular 1.0, metallic 1   coloured highlights, no diffuse light
#include "app/json_reader.h"
#include "physics/shape.h"
#include "render/scene_view.h"

#include <string>

namespace tumble::app {

// Throws SceneError for an unknown preset (listing them) or a knob outside [0, 1].
render::Material read_material(JsonReader r);

// What a body without a `material` looks like: matte for planes, plastic otherwise.
render::Material default_material(physics::ShapeKind kind);

std::string material_preset_names(); // "plastic, glossy, matte, rubber, metal"

} // namespace tumble::app
