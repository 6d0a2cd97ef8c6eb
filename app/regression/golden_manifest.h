#pragma once
// Golden images: committed pictures of chosen frames, and the manifest that says how each is made
// and how closely a new rendering must match it. A manifest (JSON) looks like
//   {"gl_renderer": "...", "gl_version": "...",
//    "compare": {"tolerance": 2, "perceptual_threshold": 0.05, "max_different": 20},
//    "images": [{"scene": "default", "frame": 0, "width": 320, "height": 180}, ...]}
// Each image lives beside the manifest as <scene>_<frame, 4 digits>.png (..._overlay.png with the
// text overlay). An entry may carry its own "compare" object, overriding the defaults field by
// field, and "overlay": true to draw the scene's text overlay (off otherwise: its numbers move
// with the last digit of the physics, which is not what a golden image is for). Every other
// picture setting (shadows, anti-aliasing, camera, axes) is the scene's own.
#include "render/image_compare.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tumble::app {

struct GoldenEntry {
    std::string scene; // built-in name, or a path relative to the manifest's folder
    std::int64_t frame = 0;
    int width = 320;
    int height = 180;
    bool overlay = false;
    render::CompareOptions compare;
    std::filesystem::path image; // the golden PNG
    std::string label() const;   // "<scene> frame <k>"
};

struct GoldenManifest {
    std::filesystem::path path;
    std::string gl_renderer, gl_version; // of the machine the goldens were made on
    std::vector<GoldenEntry> entries;
};

GoldenManifest load_golden_manifest(const std::filesystem::path& path); // throws SceneError

// Rewrites the manifest's renderer fields and appends `added` to its images, atomically; the
// rest of the file is kept as it is.
void save_golden_manifest(const GoldenManifest& manifest,
                          const std::vector<GoldenEntry>& added = {});

// The goldens a new scene gets: its first, middle and last frames (of `frames`) at 320x180 with
// the manifest's compare settings.
std::vector<GoldenEntry> new_scene_entries(const GoldenManifest& manifest, const std::string& scene,
                                           std::int64_t frames);

} // namespace tumble::app
