#pragma once
// Which GL renderer drew each golden image, and from which scene: `golden-renderers.json` in the
// goldens' folder, written by `tumble test --update` and read by every run, so that a golden made
// on another renderer (another Mesa, a GPU driver) is reported as such, check by check, and is
// not replaced from a different renderer without --force; and so that the report can say when a
// scene has changed since its goldens were made. Machine-written; people need not edit it:
//   {"format_version": 1,
//    "images": {"default_0000.png": {"gl_renderer": "llvmpipe (...)", "gl_version": "4.5 ...",
//                                    "scene_content_hash": "0123456789abcdef"}}}
// (the scene's hash, app/scene/content_hash.h, is absent for goldens made before it was kept).
#include "app/regression/check_result.h"

#include <filesystem>
#include <map>
#include <string>

namespace tumble::app {

class GoldenRenderers {
  public:
    static constexpr const char* kFileName = "golden-renderers.json";

    // The record in `goldens` (a folder); none yet is an empty record. Throws SceneError when
    // the file is not such a record.
    static GoldenRenderers load(const std::filesystem::path& goldens);

    GlIdentity of(const std::string& image_file) const; // empty when not recorded
    // The content hash of the scene the image was drawn from (16 hex digits); "" when not kept.
    std::string scene_hash_of(const std::string& image_file) const;
    void set(const std::string& image_file, const GlIdentity& gl, const std::string& scene_hash);
    void save() const; // atomically (io/atomic_file.h)

  private:
    std::filesystem::path path_;
    struct Entry {
        GlIdentity gl;
        std::string scene_hash;
    };
    std::map<std::string, Entry> images_;
};

} // namespace tumble::app
