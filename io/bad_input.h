#pragma once
// Input the user gave that Tumble cannot use: a scene file, a command-line option, an output name
// or folder. Commands exit with 2 for it (README, "Exit codes"). Every library above io that
// rejects an input throws this or a subclass (app's SceneError names file and place); anything
// else that escapes a command is a failed run, exit 1. The one mapping: app/cli/failure.h.
#include <stdexcept>

namespace tumble::io {

struct BadInput : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace tumble::io
