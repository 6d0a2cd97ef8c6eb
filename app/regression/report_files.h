#pragma once
// Where a report's files go, and how text outputs are written: the HTML report's images live in
// <report>/images/ as <check>.expected.png, <check>.actual.png and <check>.diff.png, named the
// same from the HTML and from the JUnit file's attachments.
#include "app/regression/check_result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tumble::app {

struct ReportImages {
    std::filesystem::path expected, actual, diff; // relative to the report's folder; empty: none
};

// The images the report shows for an image check: for a failure the golden (if readable), the
// drawing and the diff (same size only); for a pass only the drawing.
ReportImages report_images(const CheckResult& result);
// The same, as paths under `report` that exist once the report is written.
std::vector<std::filesystem::path> report_images(const std::filesystem::path& report,
                                                 const CheckResult& result);

// Writes `text` to `path` atomically, creating missing parent folders (io/atomic_file.h).
void write_text_file(const std::filesystem::path& path, const std::string& text);

} // namespace tumble::app
