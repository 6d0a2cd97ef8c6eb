#pragma once
// Reads one entry of the scene's "bodies" array into a physics BodyDef and its look.
#include "app/scene/json_reader.h"
#include "app/scene/scene.h"
#include "app/scene/shape_loader.h"

namespace tumble::app {

void read_body(JsonReader r, int index, ShapeContext& shapes, physics::BodyDef& body,
               BodyLook& look);

} // namespace tumble::app
