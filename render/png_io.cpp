#include "render/png_io.h"

#include "io/atomic_file.h"

#include <png.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>

namespace tumble::render {

namespace fs = std::filesystem;

const char* to_string(PngEncoder encoder) {
    switch (encoder) {
    case PngEncoder::libpng:
        return "libpng";
    case PngEncoder::stb:
        return "stb_image_write";
    }
    return "?";
}

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// ---- libpng ------------------------------------------------------------------------------------

// libpng reports an error by calling on_libpng_error, which must not return: it longjmps back to
// the setjmp in encode_libpng. The message waits here for the exception thrown afterwards.
struct LibpngError {
    char text[200] = "unknown libpng error";
};

[[noreturn]] void on_libpng_error(png_structp png, png_const_charp message) {
    auto* error = static_cast<LibpngError*>(png_get_error_ptr(png));
    std::snprintf(error->text, sizeof error->text, "%s", message);
    png_longjmp(png, 1);
}

void on_libpng_warning(png_structp, png_const_charp) {}

// Encodes `image` into an open file. A longjmp skips C++ destructors, so nothing in this function
// has one: it returns false with the message in `error` instead of throwing.
bool encode_libpng(std::FILE* file, const Image& image, int level, LibpngError* error) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, error, on_libpng_error, on_libpng_warning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) { // we land here when libpng fails below
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, file);
    png_set_compression_level(png, level);
    // One fixed filter instead of libpng's adaptive choice per row: "sub" stores each byte as the
    // difference from the same channel one pixel to the left, which turns smooth gradients into
    // runs of small numbers that deflate well, at almost no cost.
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
                 static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) png_write_row(png, image.row(y));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

// ---- stb_image_write ---------------------------------------------------------------------------

struct StbOutput {
    std::FILE* file;
    bool ok = true;
    int error = 0; // errno of the failed write
};

void stb_write_to_file(void* context, void* data, int size) {
    auto* out = static_cast<StbOutput*>(context);
    const auto bytes = static_cast<std::size_t>(size);
    if (out->ok && std::fwrite(data, 1, bytes, out->file) != bytes) {
        out->ok = false;
        out->error = errno;
    }
}

// stb keeps its compression setting in a process-wide variable (stbi_write_png_compression_level)
// rather than a parameter, so writers serialise on this mutex while they set, use and restore
// it. Note that stb's "level" is the length of its match chains, clamped to at least 5: levels
// 0..5 all behave alike, and its deflate always uses the fixed Huffman table.
bool encode_stb(std::FILE* file, const Image& image, int level, std::string* error) {
    static std::mutex level_mutex;
    const std::lock_guard lock(level_mutex);
    const int saved = stbi_write_png_compression_level;
    stbi_write_png_compression_level = level;
    StbOutput out{file};
    const int ok = stbi_write_png_to_func(stb_write_to_file, &out, image.width, image.height, 3,
                                          image.rgb.data(), image.width * 3);
    stbi_write_png_compression_level = saved;
    if (!out.ok)
        *error = std::strerror(out.error);
    else if (ok == 0)
        *error = "stb_image_write failed (out of memory?)";
    return ok != 0 && out.ok;
}

void check_writable_image(const fs::path& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
        throw PngError("cannot write '" + path.string() + "': the image is empty or its size (" +
                       std::to_string(image.width) + "x" + std::to_string(image.height) +
                       ") does not match its pixel buffer");
    }
}

} // namespace

void write_png(const fs::path& path, const Image& image, const PngWriteOptions& options) {
    check_writable_image(path, image);
    io::AtomicFile atomic(path); // deletes the temporary file on every early exit
    File file(std::fopen(atomic.temp_path().c_str(), atomic.fopen_mode()));
    if (!file) {
        const int error = errno; // before anything else can change it
        throw PngError("cannot write '" + path.string() + "': cannot create '" +
                       atomic.temp_path().filename().string() + "': " + std::strerror(error));
    }
    const int level = std::clamp(options.level, 0, 9);
    LibpngError libpng_error;
    std::string stb_error;
    errno = 0;
    const bool encoded = options.encoder == PngEncoder::libpng
                             ? encode_libpng(file.get(), image, level, &libpng_error)
                             : encode_stb(file.get(), image, level, &stb_error);
    const int encode_error = errno; // libpng's "Write Error" comes from a failed fwrite
    const int close_status = std::fclose(file.release()); // flushes: may report a full disk
    const int close_error = errno;
    if (!encoded || close_status != 0) {
        std::string why = std::strerror(close_error);
        if (!encoded) {
            why = options.encoder == PngEncoder::libpng ? libpng_error.text : stb_error;
            if (encode_error != 0 && options.encoder == PngEncoder::libpng)
                why += std::string(": ") + std::strerror(encode_error); // e.g. No space left
        }
        const std::string reason = why + " (" + to_string(options.encoder) + ")";
        throw PngError("cannot write '" + path.string() + "': " + reason, reason);
    }
    try {
        atomic.commit();
    } catch (const io::FileError& e) {
        throw PngError(e.what());
    }
}

Image read_png(const fs::path& path) {
    File file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        const int error = errno;
        throw PngError("cannot open '" + path.string() + "': " + std::strerror(error));
    }
    // stb_image reads many formats; golden images and `tumble diff` promise PNG, so check the
    // eight-byte signature first and give a clear message for anything else.
    unsigned char signature[8] = {};
    if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
        throw PngError("'" + path.string() + "' is not a PNG file");
    }
    std::rewind(file.get());
    int width = 0, height = 0, channels_in_file = 0;
    if (stbi_info_from_file(file.get(), &width, &height, &channels_in_file) &&
        static_cast<long long>(width) * height > kMaxReadPixels) {
        throw PngError("'" + path.string() + "' is " + std::to_string(width) + "x" +
                       std::to_string(height) + " pixels; Tumble reads PNGs of at most " +
                       std::to_string(kMaxReadPixels >> 20) + " Mpx");
    }
    // Asking for 3 channels makes stb expand gray and palettes and drop alpha.
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_file(file.get(), &width, &height, &channels_in_file, 3), stbi_image_free);
    if (!pixels) {
        throw PngError("cannot decode '" + path.string() + "': " + stbi_failure_reason());
    }
    Image image(width, height);
    std::memcpy(image.rgb.data(), pixels.get(), image.rgb.size());
    return image;
}

} // namespace tumble::render
