#pragma once
// The render benchmark's fixed cases (bench/README.md has the table and what each one answers):
// issue 5's targets (the default demo at 720p into MP4 and PNG, a 1000-sphere scene, the preview),
// then the cost of each effect of issue 14 on the default demo against `default-720p-hard`, GIF
// output, and issue 16's teaching overlays. Fixed so that results kept as CSV compare across runs.
#include "app/scene/scene.h"

#include <span>
#include <string>
#include <vector>

namespace tumble::bench {

struct RenderCase {
    const char* name;
    const char* scene; // a built-in scene, or a file of bench/scenes/ ("spheres1000")
    const char* sink;  // "mp4", "png" or "gif"
    bool preview;
    bool shadows, antialiasing;
    int width, height;
    int frames, quick_frames;
    // The effects of issue 14, each on or off (the scene's defaults: soft shadows and AO on).
    bool soft_shadows = true, ambient_occlusion = true, reflections = false;
    // Issue 16's overlays: charts of the book's energy and w_body, trails, Poinsot's construction.
    bool teaching = false;
};

std::span<const RenderCase> render_cases();

// The cases named (all of them for none), in the table's order. Throws io::BadInput naming the
// cases there are when a name is not one of them.
std::vector<const RenderCase*> select_cases(const std::vector<std::string>& names);

// The case's scene: bench/scenes/<scene>.json of the source tree (scripts/make-scenes.py writes
// it) when there is one, else the built-in scene of that name.
app::Scene load_case_scene(const RenderCase& c);

// "soft-shadows+msaa4+ao", "preview", ...: the switches of a case, for the table and the CSV.
std::string options_label(const RenderCase& c);

} // namespace tumble::bench
