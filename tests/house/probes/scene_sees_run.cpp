// Must NOT compile: app/scene/ cannot see app/run/, the layer above it. Built only by the test
// House.SceneCannotIncludeRun, which passes when the compiler says the header is not found.
#include "app/run/simulation.h"
