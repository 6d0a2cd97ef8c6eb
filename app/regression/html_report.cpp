#include "app/regression/html_report.h"

#include "app/regression/golden_renderers.h"
#include "app/regression/junit_report.h"
#include "app/regression/report_files.h"
#include "app/regression/suite_runner.h"
#include "app/regression/svg_plot.h"
#include "app/run/trajectory_reader.h"
#include "app/scene/content_hash.h"
#include "io/atomic_file.h"
#include "io/bad_input.h"
#include "render/png_io.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

namespace tumble::app {
namespace {

std::string esc(const std::string& s) {
    return xml_escape(s);
}

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// The displayed size of a picture: in the viewer twice its pixels (to see them), at most 720
// wide; side by side at most 360 wide, so that golden, drawing and diff fit in one row.
std::pair<int, int> shown_size(const render::Image& image, double widest = 720) {
    const double scale = std::min(2.0, widest / std::max(1, image.width));
    return {int(image.width * scale), int(image.height * scale)};
}

std::string masks_html(const ImageCheck& c) {
    std::string out;
    for (const Mask& m : c.masks)
        out += "<div class=\"mask\" title=\"masked: ignored\" style=\"left:" +
               fmt("%.3f", 100.0 * m.x / c.width) + "%;top:" + fmt("%.3f", 100.0 * m.y / c.height) +
               "%;width:" + fmt("%.3f", 100.0 * m.width / c.width) +
               "%;height:" + fmt("%.3f", 100.0 * m.height / c.height) + "%\"></div>";
    return out;
}

std::string figure(const std::string& caption, const std::filesystem::path& src,
                   const render::Image& image, const ImageCheck& c) {
    const auto [w, h] = shown_size(image, 360);
    return "<figure><figcaption>" + caption +
           "</figcaption><div class=\"stack\"><img class=\"pixels\" src=\"" + esc(src.string()) +
           "\" width=\"" + std::to_string(w) + "\" height=\"" + std::to_string(h) + "\" alt=\"" +
           esc(caption) + "\">" + masks_html(c) + "</div></figure>\n";
}

std::string compare_tools(const ReportImages& files, const render::Image& image) {
    const auto [w, h] = shown_size(image);
    const std::string size =
        "width=\"" + std::to_string(w) + "\" height=\"" + std::to_string(h) + "\"";
    return "<div class=\"compare\"><div class=\"tools\"><input type=\"range\" min=\"0\" "
           "max=\"100\" "
           "value=\"50\" aria-label=\"golden | this run\"><button class=\"blink\" "
           "type=\"button\">blink</button><span class=\"shown\"></span></div>\n"
           "<div class=\"viewer\" style=\"width:" +
           std::to_string(w) + "px;height:" + std::to_string(h) + "px\"><img src=\"" +
           esc(files.actual.string()) + "\" " + size +
           " alt=\"this run\"><div class=\"over\" style=\"width:50%\"><img src=\"" +
           esc(files.expected.string()) + "\" " + size + " alt=\"golden\"></div></div></div>\n";
}

std::string image_numbers(const CheckResult& r, const GlIdentity& here) {
    const ImageCheck& c = *r.image;
    const render::CompareResult& cr = r.image_outcome.compare;
    std::ostringstream o;
    o << "<table class=\"numbers\"><tr><th>differing pixels</th><th>allowed</th>"
         "<th>anti-aliased</th><th>max channel delta</th><th>tolerance</th><th>YIQ threshold</th>"
         "<th>size</th><th>masks</th></tr><tr><td>"
      << cr.different << "</td><td>" << c.compare.max_different << "</td><td>" << cr.antialiased
      << "</td><td>" << cr.max_channel_delta << "</td><td>" << c.compare.tolerance << "</td><td>"
      << c.compare.perceptual_threshold << "</td><td>" << c.width << "x" << c.height << "</td><td>"
      << c.masks.size() << "</td></tr></table>\n";
    o << "<table class=\"gl\"><tr><th></th><th>GL_RENDERER</th><th>GL_VERSION</th></tr>"
      << "<tr><td>golden</td><td>" << esc(r.image_outcome.golden_gl.renderer) << "</td><td>"
      << esc(r.image_outcome.golden_gl.version) << "</td></tr><tr><td>this run</td><td>"
      << esc(here.renderer) << "</td><td>" << esc(here.version) << "</td></tr></table>\n";
    return o.str();
}

std::string image_body(const CheckResult& r, const GlIdentity& here) {
    const ReportImages files = report_images(r);
    const ImageOutcome& o = r.image_outcome;
    std::string out = "<div class=\"images\">\n";
    if (!files.expected.empty()) out += figure("golden", files.expected, o.expected, *r.image);
    if (!files.actual.empty()) out += figure("this run", files.actual, o.actual, *r.image);
    if (!files.diff.empty())
        out +=
            figure("diff: red differs, yellow anti-aliased", files.diff, o.compare.diff, *r.image);
    out += "</div>\n";
    if (!files.expected.empty() && o.compare.same_size) out += compare_tools(files, o.actual);
    if (o.compare.same_size) out += image_numbers(r, here);
    return out;
}

std::string state_body(const CheckResult& r) {
    std::ostringstream o;
    const std::vector<Series>& all = r.state_outcome.series;
    if (all.empty()) return "";
    o << "<table class=\"numbers\"><tr><th>body</th><th>quantity</th><th>tolerance</th>"
         "<th>largest deviation</th><th>at t (s)</th><th>first out of tolerance</th></tr>\n";
    for (const Series& s : all) {
        const std::string unit = quantity_unit(s.quantity);
        o << "<tr><td>" << esc(s.body.empty() ? "(scene)" : s.body) << "</td><td>"
          << quantity_name(s.quantity) << "</td><td>" << fmt("%.3g ", s.tolerance) << unit
          << "</td><td>" << fmt("%.3g ", s.deviation[s.worst]) << unit << "</td><td>"
          << fmt("%.6g", s.t[s.worst]) << "</td><td>"
          << (s.passed() ? "never" : "t = " + fmt("%.6g s", s.t[std::size_t(s.first_out)]))
          << "</td></tr>\n";
    }
    o << "</table>\n";
    // Plots: every series out of tolerance; for a pass, the one closest to its tolerance.
    std::vector<const Series*> plotted;
    for (const Series& s : all)
        if (!s.passed()) plotted.push_back(&s);
    if (plotted.empty())
        plotted.push_back(
            &*std::max_element(all.begin(), all.end(), [](const Series& a, const Series& b) {
                return a.ratio() < b.ratio();
            }));
    for (const Series* s : plotted)
        o << "<figure><figcaption>" << esc(s->body.empty() ? "scene" : "body \"" + s->body + "\"")
          << "</figcaption>" << svg_plot(*s) << "</figure>\n";
    return o.str();
}

// The scene's content hash now against the one its golden was made from ("" when unknown).
std::string golden_scene_hash(const CheckResult& r, const GoldenRenderers& record) {
    if (r.image) return record.scene_hash_of(r.image->golden.filename().string());
    try {
        const std::optional<SceneRecord> kept = read_scene_record(r.state->golden);
        return kept ? kept->content_hash : "";
    } catch (const io::BadInput&) { // the check itself says what is wrong with the golden
        return "";
    }
}

std::string scene_change_note(const CheckResult& r, const GoldenRenderers& record) {
    const std::string then = golden_scene_hash(r, record);
    const std::string now = ContentHash::to_hex(r.scene->scene.content_hash);
    if (then.empty() || then == now) return "";
    return "the scene has changed since this golden was made (content hash " + now +
           ", the golden's " + then + "): a difference may come from the scene, not the code";
}

std::string subtitle(const CheckResult& r) {
    if (r.image)
        return "image &middot; " + esc(r.scene->name) + " &middot; frame " +
               std::to_string(r.image->frame) + (r.image->overlay ? " with overlay" : "");
    return "state &middot; " + esc(r.scene->name) + " &middot; " +
           std::to_string(r.state->frames.size()) + " frames";
}

std::string section(const CheckResult& r, const GlIdentity& here, const GoldenRenderers& record) {
    std::ostringstream o;
    const char* status = r.passed ? "passed" : "failed";
    o << "<section class=\"check " << status << "\" id=\"check-" << esc(r.name())
      << "\" data-check=\"" << esc(r.name()) << "\" data-status=\"" << status << "\">\n"
      << "<h3><span class=\"badge\">" << (r.passed ? "PASS" : "FAIL") << "</span>" << esc(r.name())
      << "<small>" << subtitle(r) << "</small></h3>\n"
      << "<p class=\"summary\">" << esc(r.summary) << "</p>\n";
    std::vector<std::string> details = r.details;
    if (const std::string note = scene_change_note(r, record); !note.empty())
        details.insert(details.begin(), note);
    if (!details.empty()) {
        o << "<ul class=\"details\">";
        for (const std::string& d : details) o << "<li>" << esc(d) << "</li>";
        o << "</ul>\n";
    }
    if (!r.run_failed) o << (r.image ? image_body(r, here) : state_body(r));
    if (!r.update.empty())
        o << "<p class=\"update\">"
          << (r.golden_missing ? "To create the golden" : "To accept this run as the new golden")
          << ": <code>" << esc(r.update) << "</code></p>\n";
    o << "</section>\n";
    return o.str();
}

std::string header(const Suite& suite, const SuiteRun& run) {
    const std::size_t failed = run.failed(), total = run.results.size();
    std::map<std::string, int> golden_gl; // renderers of the goldens shown, with counts
    for (const CheckResult& r : run.results)
        if (r.image && r.image_outcome.golden_gl.known())
            ++golden_gl[r.image_outcome.golden_gl.renderer + "\n" +
                        r.image_outcome.golden_gl.version];
    std::ostringstream o;
    o << "<header><h1>Tumble regression report"
      << (suite.title.empty() ? "" : ": " + esc(suite.title))
      << "</h1>\n<p class=\"totals\"><span class=\"" << (failed ? "bad" : "good") << "\">" << failed
      << " failed</span>, " << total - failed << " passed of " << total
      << " checks &middot; suite <code>" << esc(suite.path.string()) << "</code> &middot; "
      << run.jobs << " job(s) &middot; " << fmt("%.1f s", run.seconds) << "</p>\n";
    o << "<table class=\"gl\"><tr><th>GL renderer</th><th>GL_RENDERER</th><th>GL_VERSION</th></tr>"
      << "<tr><td>this run</td><td>" << esc(run.gl.renderer) << "</td><td>" << esc(run.gl.version)
      << "</td></tr>";
    for (const auto& [gl, count] : golden_gl) {
        const auto cut = gl.find('\n');
        o << "<tr><td>goldens (" << count << " images)</td><td>" << esc(gl.substr(0, cut))
          << "</td><td>" << esc(gl.substr(cut + 1)) << "</td></tr>";
    }
    o << "</table>\n<p>Update every failing golden: <code>tumble test " << esc(suite.path.string())
      << " --update</code></p></header>\n";
    return o.str();
}

// The passed or the failed checks: failed state checks before failed image checks (a state that
// moved explains the pictures that moved with it), each kind in suite order; passes in suite
// order.
std::vector<const CheckResult*> in_report_order(const SuiteRun& run, bool failed) {
    std::vector<const CheckResult*> out;
    for (const CheckResult& r : run.results)
        if (r.passed != failed) out.push_back(&r);
    if (failed)
        std::stable_partition(out.begin(), out.end(),
                              [](const CheckResult* r) { return r->state != nullptr; });
    return out;
}

void write_images(const std::filesystem::path& dir, const CheckResult& r) {
    const ReportImages files = report_images(r);
    const ImageOutcome& o = r.image_outcome;
    const render::PngWriteOptions small{render::PngEncoder::libpng, 6};
    if (!files.expected.empty()) render::write_png(dir / files.expected, o.expected, small);
    if (!files.actual.empty()) render::write_png(dir / files.actual, o.actual, small);
    if (!files.diff.empty()) render::write_png(dir / files.diff, o.compare.diff, small);
}

} // namespace

void write_html_report(const std::filesystem::path& dir, const Suite& suite, const SuiteRun& run) {
    io::ensure_writable_directory(dir / "images");
    std::ostringstream html;
    const std::size_t failed = run.failed();
    html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
         << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
         << "<title>" << (failed ? std::to_string(failed) + " failed" : std::string("all passed"))
         << " - Tumble test " << esc(suite.path.filename().string()) << "</title>\n<style>"
         << report_style() << "</style></head>\n<body>\n"
         << header(suite, run) << "<main>\n";
    const GoldenRenderers record = GoldenRenderers::load(suite.goldens);
    for (const bool want_failed : {true, false}) {
        const std::size_t count = want_failed ? failed : run.results.size() - failed;
        if (count == 0) continue;
        html << "<h2 class=\"group\">" << (want_failed ? "Failed" : "Passed") << " (" << count
             << ")</h2>\n";
        for (const CheckResult* r : in_report_order(run, want_failed)) {
            if (r->image) write_images(dir, *r);
            html << section(*r, run.gl, record);
        }
    }
    html << "</main>\n<script>" << report_script() << "</script>\n</body></html>\n";
    write_text_file(dir / "index.html", html.str());
}

} // namespace tumble::app
