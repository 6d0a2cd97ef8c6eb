// Must NOT compile: render/ cannot see app/ (cmake/TumbleLibrary.cmake). Built only by the test
// House.RenderCannotIncludeApp, which passes when the compiler says the header is not found.
#include "app/scene/scene.h"
