// Fuzz target: the regression suite reader (app/regression/suite.h), which also loads the scenes
// a suite names. The input is written as suite.json to a per-process scratch folder and loaded
// from there. Asserts: a suite (never from a text with a NUL byte) whose every check has a name
// of letters, digits, '_', '.' and '-', a golden file of that name in the suite's golden folder,
// frames inside its scene's run, masks inside its image and a state check's bodies found in its
// scene; or io::BadInput (SceneError) with a short message naming the suite or the scene it
// names; any other exception, a crash, a hang or a sanitizer report is a finding.
#include "app/regression/suite.h"
#include "harness_support.h"
#include "io/bad_input.h"

#include <cstddef>
#include <cstdint>
#include <regex>
#include <string>

namespace {

using tumble::fuzz::require;

void check_names(const std::string& name, const std::filesystem::path& golden,
                 const tumble::app::Suite& suite) {
    static const std::regex ok("^[A-Za-z0-9][A-Za-z0-9_.-]*$");
    require(std::regex_match(name, ok), "check names are file-name safe", name);
    require(golden.parent_path() == suite.goldens, "goldens lie in the golden folder", name);
    require(golden.stem() == name, "a golden is named after its check", name);
}

void check_suite(const tumble::app::Suite& suite) {
    for (const tumble::app::SuiteScene& s : suite.scenes) {
        for (const tumble::app::ImageCheck& c : s.images) {
            check_names(c.name, c.golden, suite);
            require(c.frame >= 0 && c.frame < s.timeline.frames, "frames lie in the run", c.name);
            require(c.width >= 16 && c.height >= 16, "image sizes are in range", c.name);
            for (const tumble::app::Mask& m : c.masks)
                require(m.x >= 0 && m.y >= 0 && m.x + m.width <= c.width &&
                            m.y + m.height <= c.height,
                        "masks lie in the image", c.name);
        }
        for (const tumble::app::StateCheck& c : s.states) {
            check_names(c.name, c.golden, suite);
            require(!c.frames.empty() && c.frames.back() < s.timeline.frames,
                    "frames lie in the run", c.name);
            require(c.bodies.size() == c.body_indices.size(), "every body is found", c.name);
            for (int b : c.body_indices)
                require(b >= 0 && b < int(s.scene.bodies.size()), "body indices are valid", c.name);
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path path = tumble::fuzz::write_scratch("suite.json", data, size);
    try {
        const tumble::app::Suite suite = tumble::app::load_suite(path);
        const std::string text(reinterpret_cast<const char*>(data), size);
        require(text.find('\0') == std::string::npos, "a NUL byte is refused (JSON has none)");
        check_suite(suite);
        tumble::fuzz::last_verdict() = tumble::fuzz::Verdict::kLoaded;
    } catch (const tumble::io::BadInput& e) {
        tumble::fuzz::last_verdict() = tumble::fuzz::Verdict::kRefused;
        const std::string what = e.what();
        require(what.size() <= 4096, "the error message is short", what);
        require(!what.empty(), "the error message says something", what);
    }
    return 0;
}
