#pragma once
// A suite run as JUnit XML, the format CI servers read (GitLab's artifacts:reports:junit,
// Jenkins' junit step, GitHub actions that publish test results): one <testsuite> per scene, one
// <testcase> per check, a <failure> carrying the numbers in its message. It follows the schema
// of the Jenkins xUnit plugin (junit-10.xsd), which pytest also writes to; tests/app/regression
// checks it with xmllint against tests/data/junit.xsd, which states that schema's rules.
#include "app/regression/check_result.h"

#include <filesystem>

namespace tumble::app {

// Writes atomically (io/atomic_file.h). `report` is the HTML report's folder, or empty: when
// given, a failing image check's images are attached (GitLab's [[ATTACHMENT|path]] convention).
void write_junit(const std::filesystem::path& path, const Suite& suite, const SuiteRun& run,
                 const std::filesystem::path& report);

// `text` escaped for XML character data and attribute values; characters XML 1.0 cannot hold
// (controls other than tab, newline and carriage return) become '?'.
std::string xml_escape(const std::string& text);

} // namespace tumble::app
