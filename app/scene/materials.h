#pragma once
// A body's `material` in the scene file: how its surface looks (the three knobs of
// render::Material) and how it touches (physics::Material: friction, restitution). Either a
// preset name or an object {"preset", "roughness", "specular", "metallic", "friction",
// "restitution"} (docs/scene-format.md). Presets set only the look:
//   plastic  roughness 0.45, specular 0.5   the default for solid bodies
//   glossy   roughness 0.15, specular 0.8   lacquer, polished stone
//   matte    roughness 0.9,  specular 0.1   the default for planes: paper, chalk, concrete
//   rubber   roughness 0.7,  specular 0.2
//   metal    roughness 0.2,  specular 1.0, metallic 1   coloured highlights, no diffuse light
#include "app/scene/json_reader.h"
#include "physics/contact_model.h"
#include "physics/shape.h"
#include "render/scene_view.h"

#include <string>

namespace tumble::app {

// The look; `contact` gets the friction (>= 0) and restitution (in [0, 1]) when given. An object
// without "preset" starts from default_material(kind). Throws SceneError for an unknown preset
// (listing them) or a value out of its range.
render::Material read_material(JsonReader r, physics::ShapeKind kind, physics::Material& contact);

// What a body without a `material` looks like: matte for planes, plastic otherwise.
render::Material default_material(physics::ShapeKind kind);

std::string material_preset_names(); // "plastic, glossy, matte, rubber, metal"

} // namespace tumble::app
