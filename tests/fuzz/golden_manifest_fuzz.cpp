// Fuzz target: the golden-image manifest reader (app/regression/golden_manifest.h). The input is
// written as goldens.json to a per-process scratch folder and loaded from there. Asserts: a
// manifest (never from a text with a NUL byte) whose every image lies in the manifest's own folder
// with a frame >= 0 and a size in range, or io::BadInput (SceneError) with a short message naming
// the manifest file; any other exception, a crash, a hang or a sanitizer report is a finding.
#include "app/regression/golden_manifest.h"
#include "harness_support.h"
#include "io/bad_input.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using tumble::fuzz::require;
    const std::filesystem::path path = tumble::fuzz::write_scratch("goldens.json", data, size);
    try {
        const tumble::app::GoldenManifest m = tumble::app::load_golden_manifest(path);
        const std::string text(reinterpret_cast<const char*>(data), size);
        require(text.find('\0') == std::string::npos, "a NUL byte is refused (JSON has none)");
        for (const tumble::app::GoldenEntry& e : m.entries) {
            require(e.image.parent_path() == path.parent_path(), "images lie beside the manifest");
            require(e.image.extension() == ".png", "images are PNG files");
            require(e.frame >= 0, "frames count from 0");
            require(e.width >= 16 && e.height >= 16, "image sizes are in range");
        }
    } catch (const tumble::io::BadInput& e) {
        tumble::fuzz::require_clear_error(e.what(), path.string());
    }
    return 0;
}
