#include "app/regression/junit_report.h"

#include "app/regression/report_files.h"
#include "io/atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

namespace tumble::app {
namespace {

std::string seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", s);
    return buf;
}

std::string attribute(const char* name, const std::string& value) {
    return std::string(" ") + name + "=\"" + xml_escape(value) + "\"";
}

std::string timestamp() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &utc);
    return buf;
}

std::string hostname() {
    char buf[256] = {};
    return gethostname(buf, sizeof buf - 1) == 0 ? buf : "";
}

void write_case(std::ostream& out, const CheckResult& r, const std::filesystem::path& report) {
    out << "    <testcase" << attribute("name", r.name())
        << attribute("classname", r.scene->name + "." + r.kind())
        << attribute("time", seconds(r.seconds));
    if (r.passed) {
        out << "/>\n";
        return;
    }
    out << ">\n";
    {
        std::string text = r.summary;
        for (const std::string& d : r.details) text += "\n" + d;
        if (!r.update.empty() && !r.golden_missing) text += "\nupdate: " + r.update;
        out << "      <failure" << attribute("message", r.summary)
            << attribute("type", std::string(r.kind()) + " check") << ">" << xml_escape(text)
            << "</failure>\n";
        std::string attachments;
        if (!report.empty() && r.image)
            for (const std::filesystem::path& image : report_images(report, r))
                attachments += "[[ATTACHMENT|" + image.string() + "]]\n";
        if (!attachments.empty())
            out << "      <system-out>" << xml_escape(attachments) << "</system-out>\n";
    }
    out << "    </testcase>\n";
}

} // namespace

std::string xml_escape(const std::string& text) {
    std::string out;
    for (char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&apos;";
            break;
        default:
            out += (c < 0x20 && c != '\t' && c != '\n' && c != '\r') ? '?' : ch;
        }
    }
    return out;
}

void write_junit(const std::filesystem::path& path, const Suite& suite, const SuiteRun& run,
                 const std::filesystem::path& report) {
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml << "<testsuites"
        << attribute("name", suite.title.empty() ? suite.path.string() : suite.title)
        << attribute("tests", std::to_string(run.results.size()))
        << attribute("failures", std::to_string(run.failed())) << attribute("errors", "0")
        << attribute("time", seconds(run.seconds)) << ">\n";
    const std::string stamp = timestamp(), host = hostname();
    for (std::size_t i = 0; i < suite.scenes.size(); ++i) {
        const SuiteScene& scene = suite.scenes[i];
        std::size_t tests = 0, failures = 0;
        for (const CheckResult& r : run.results)
            if (r.scene == &scene) ++tests, failures += !r.passed;
        if (tests == 0) continue;
        xml << "  <testsuite" << attribute("name", scene.name)
            << attribute("tests", std::to_string(tests))
            << attribute("failures", std::to_string(failures)) << attribute("errors", "0")
            << attribute("skipped", "0") << attribute("time", seconds(run.scene_seconds[i]))
            << attribute("timestamp", stamp) << attribute("hostname", host)
            << attribute("file", suite.path.string()) << ">\n";
        xml << "    <properties>\n"
            << "      <property" << attribute("name", "scene")
            << attribute("value", scene.scene.source) << "/>\n"
            << "      <property" << attribute("name", "gl_renderer")
            << attribute("value", run.gl.renderer) << "/>\n"
            << "      <property" << attribute("name", "gl_version")
            << attribute("value", run.gl.version) << "/>\n"
            << "    </properties>\n";
        for (const CheckResult& r : run.results)
            if (r.scene == &scene) write_case(xml, r, report);
        xml << "  </testsuite>\n";
    }
    xml << "</testsuites>\n";
    write_text_file(path, xml.str());
}

} // namespace tumble::app
