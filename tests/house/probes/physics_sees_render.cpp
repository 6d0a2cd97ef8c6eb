// Must NOT compile: physics/ cannot see render/ (cmake/TumbleLibrary.cmake). Built only by the
// test House.PhysicsCannotIncludeRender, which passes when the compiler says the header is not
// found.
#include "render/renderer.h"
