#pragma once
// `tumble test --report DIR`: a self-contained HTML report a reviewer opens in a browser (no
// network: inline CSS and a little JavaScript, images as files in DIR/images/). Failures come
// first, failed state checks before failed image checks; a check whose scene has changed since
// its golden was made says so (the scene's content hash against the golden's). A passing image
// check that is not bit-identical says so in words that do not read as a failure. An image check
// shows the golden, this run's drawing and the diff side by side, a viewer
// with a slider (golden left of it, drawing right) and a blink toggle, the masks, the numbers
// and both GL renderers; a state check shows each compared series as an SVG plot with the
// tolerance band; every failure gives the exact command that would update its golden.
#include "app/regression/check_result.h"

#include <filesystem>

namespace tumble::app {

// Writes DIR/index.html and the images (each file atomically, folders created as needed).
void write_html_report(const std::filesystem::path& dir, const Suite& suite, const SuiteRun& run);

// The report's stylesheet and script (app/regression/report_assets.cpp).
const char* report_style();
const char* report_script();

} // namespace tumble::app
