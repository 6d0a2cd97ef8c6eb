#pragma once
// PNG files <-> Image (8-bit RGB, rows top-down).
//
// Two encoders sit behind write_png. Both produce standard 8-bit RGB PNGs; they differ in speed
// and size. Measured at 1280x720 on a rendered-like picture (see tests/render/png_io_test.cpp,
// DISABLED_MeasureWriters), libpng at zlib level 1 with the "sub" filter is several times
// faster than stb_image_write, whose default tries all five PNG filters on every row and
// compresses at level 8, so libpng is the default. stb stays available as the simple,
// dependency-light reference the project started with.
#include "render/image.h"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace tumble::render {

// "cannot write 'path': reason". `reason` alone lets a caller that wrote through a temporary file
// name the file the user asked for instead.
struct PngError : std::runtime_error {
    explicit PngError(const std::string& what, std::string reason = "")
        : std::runtime_error(what), reason(reason.empty() ? what : std::move(reason)) {}
    std::string reason;
};

enum class PngEncoder {
    libpng, // zlib `level`, one fixed "sub" filter (each byte minus the one to its left):
            // cheap and effective on smooth rendered gradients
    stb,    // stb_image_write: adaptive filter per row, its own deflate at `level`
};

struct PngWriteOptions {
    PngEncoder encoder = PngEncoder::libpng;
    int level = 1; // zlib compression level 0 (store) .. 9 (smallest, slowest)
};

const char* to_string(PngEncoder encoder);

// Writes `image` to `path` atomically (temporary name in the same directory, renamed when
// complete), replacing an existing file. Throws PngError naming the file on failure, leaving
// nothing behind. Thread-safe (the stb encoder serialises on its process-wide level setting).
void write_png(const std::filesystem::path& path, const Image& image,
               const PngWriteOptions& options = {});

// Reads any PNG (gray, palette, RGB, with or without alpha, 8 or 16 bits per channel) as 8-bit
// RGB. Alpha is dropped, not composited: the result is the stored colour. 16-bit channels keep
// their high byte. Throws PngError naming the file when it is missing or not a valid PNG, or
// when its header declares more than kMaxReadPixels (checked before the pixels are allocated:
// a 100-byte PNG can claim to be 10^9 pixels).
inline constexpr long long kMaxReadPixels = 64LL << 20; // 64 Mpx: 192 MB as RGB
Image read_png(const std::filesystem::path& path);

} // namespace tumble::render
