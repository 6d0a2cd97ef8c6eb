#pragma once
// A scene the program cannot use. The message names the file, the place (JSON path such as
// /bodies/2/mass, or line:column for a syntax error) and what was expected. A kind of bad input
// (exit 2).
#include "io/bad_input.h"

#include <string>

namespace tumble::app {

struct SceneError : io::BadInput {
    SceneError(const std::string& file, const std::string& place, const std::string& what)
        : io::BadInput(format(file, place, what)), file(file), place(place) {}
    std::string file;
    std::string place;

  private:
    // "file:12:5: what" for a line:column place (the compiler convention editors jump to),
    // "file: /bodies/2/mass: what" for a JSON path.
    static std::string format(const std::string& file, const std::string& place,
                              const std::string& what) {
        const bool line_col = !place.empty() && place[0] >= '0' && place[0] <= '9';
        return file + (line_col ? ":" : ": ") + place + ": " + what;
    }
};

} // namespace tumble::app
