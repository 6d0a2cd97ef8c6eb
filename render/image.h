#pragma once
// An 8-bit RGB image with rows stored top-down (row 0 is the top of the picture), the order
// every image file and video encoder expects. OpenGL reads pixels bottom-up; the renderer flips.
#include <cstdint>
#include <vector>

namespace tumble::render {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb; // width * height * 3 bytes, row-major, top row first

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0) {}
    std::uint8_t* row(int y) { return rgb.data() + static_cast<std::size_t>(y) * width * 3; }
    const std::uint8_t* row(int y) const {
        return rgb.data() + static_cast<std::size_t>(y) * width * 3;
    }
};

} // namespace tumble::render
