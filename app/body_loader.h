#pragma once
// Reads one entry of the scene's "bodies" array into a physics BodyDef and its look.
#include "app/json_reader.h"
#include "app/scene.h"

namespace tumble::app {

void read_body(JsonReader r, int index, physics::BodyDef& body, BodyLook& look);

} // namespace tumble::app
