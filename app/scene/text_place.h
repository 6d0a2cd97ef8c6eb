#pragma once
// Places in a text for error messages, in the compiler convention editors jump to.
#include <algorithm>
#include <cstddef>
#include <string>

namespace tumble::app {

// "line:column" (1-based; a column counts bytes) of byte offset `at` in `text`.
inline std::string line_column(const std::string& text, std::size_t at) {
    at = std::min(at, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t k = 0; k < at; ++k) {
        if (text[k] == '\n')
            ++line, column = 1;
        else
            ++column;
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

} // namespace tumble::app
