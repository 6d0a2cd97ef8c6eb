#include "bench/render/render_cases.h"

#include "io/bad_input.h"

#include <algorithm>
#include <filesystem>

#ifndef TUMBLE_SOURCE_DIR
#error "TUMBLE_SOURCE_DIR: the source tree, whose bench/scenes/ holds the benchmark's own scenes"
#endif

namespace tumble::bench {
namespace {

// 720p is 1280x720; "quick" runs (--quick) take the last column's frames.
constexpr RenderCase kCases[] = {
    {"default-720p-mp4", "default", "mp4", false, true, true, 1280, 720, 600, 120},
    {"default-720p-png", "default", "png", false, true, true, 1280, 720, 240, 60},
    {"spheres1000-720p", "spheres1000", "mp4", false, true, true, 1280, 720, 120, 30},
    {"spheres1000-720p-noaa", "spheres1000", "mp4", false, true, false, 1280, 720, 120, 30},
    {"default-preview", "default", "mp4", true, false, false, 640, 360, 600, 120},
    {"default-720p-hard", "default", "mp4", false, true, true, 1280, 720, 240, 60, false, false},
    {"default-720p-soft", "default", "mp4", false, true, true, 1280, 720, 240, 60, true, false},
    {"default-720p-ao", "default", "mp4", false, true, true, 1280, 720, 240, 60, false, true},
    {"default-720p-mirror", "default", "mp4", false, true, true, 1280, 720, 240, 60, true, true,
     true},
    {"default-480p-gif", "default", "gif", false, true, true, 854, 480, 240, 60},
    {"default-480p-mp4", "default", "mp4", false, true, true, 854, 480, 240, 60},
    {"default-720p-base", "default", "mp4", false, true, true, 1280, 720, 240, 60},
    {"default-720p-teach", "default", "mp4", false, true, true, 1280, 720, 240, 60, true, true,
     false, true},
};

} // namespace

std::span<const RenderCase> render_cases() {
    return kCases;
}

std::vector<const RenderCase*> select_cases(const std::vector<std::string>& names) {
    std::vector<const RenderCase*> cases;
    for (const RenderCase& c : kCases)
        if (names.empty() || std::find(names.begin(), names.end(), c.name) != names.end())
            cases.push_back(&c);
    if (cases.size() < std::max<std::size_t>(1, names.size())) {
        std::string all;
        for (const RenderCase& c : kCases) all += std::string(all.empty() ? "" : ", ") + c.name;
        throw io::BadInput("unknown benchmark case; cases: " + all);
    }
    return cases;
}

app::Scene load_case_scene(const RenderCase& c) {
    const std::filesystem::path own = std::filesystem::path(TUMBLE_SOURCE_DIR) / "bench/scenes" /
                                      (std::string(c.scene) + ".json");
    return app::load_scene_argument(std::filesystem::exists(own) ? own.string() : c.scene);
}

std::string options_label(const RenderCase& c) {
    std::string s = c.preview ? "preview" : "";
    auto add = [&s](const char* word) {
        if (!s.empty()) s += '+';
        s += word;
    };
    if (c.shadows) add(c.soft_shadows ? "soft-shadows" : "shadows");
    if (c.antialiasing) add("msaa4");
    if (c.ambient_occlusion && !c.preview) add("ao");
    if (c.reflections) add("mirror");
    if (c.teaching) add("teach");
    return s.empty() ? "plain" : s;
}

} // namespace tumble::bench
