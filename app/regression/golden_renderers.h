#pragma once
// Which GL renderer drew each golden image: `golden-renderers.json` in the goldens' folder,
// written by `tumble test --update` and read by every run, so that a golden made on another
// renderer (another Mesa, a GPU driver) is reported as such, check by check, and is not replaced
// from a different renderer without --force. Machine-written; people need not edit it:
//   {"format_version": 1,
//    "images": {"default_0000.png": {"gl_renderer": "llvmpipe (...)", "gl_version": "4.5 ..."}}}
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
    void set(const std::string& image_file, const GlIdentity& gl);
    void save() const; // atomically (io/atomic_file.h)

  private:
    std::filesystem::path path_;
    std::map<std::string, GlIdentity> images_;
};

} // namespace tumble::app
