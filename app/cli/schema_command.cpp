// `tumble schema scene|suite`: prints the JSON Schema (draft 2020-12) of scene files or of
// regression suites, generated from the field tables the loaders read through
// (app/scene/scene_fields.h, app/regression/suite_fields.h), so editors check and complete files
// as Tumble will read them. docs/schemas/ holds the same output, kept current by a test.
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/regression/suite.h"
#include "app/regression/suite_fields.h"
#include "app/scene/json_schema.h"
#include "app/scene/scene_fields.h"

#include <cstdio>
#include <memory>

namespace tumble::app {
namespace {

int run_schema(const std::string& which) {
    const nlohmann::ordered_json schema =
        which == "scene"
            ? json_schema(scene_fields::scene(), "urn:tumble:scene:1", "Tumble scene, format 1")
            : json_schema(suite_fields::suite(),
                          "urn:tumble:suite:" + std::to_string(kSuiteFormatVersion),
                          "Tumble regression suite, format " + std::to_string(kSuiteFormatVersion));
    std::printf("%s\n", schema.dump(2).c_str());
    return std::fflush(stdout) == 0 && !std::ferror(stdout) ? kOk : kRunFailed;
}

} // namespace

Subcommand add_schema_command(CLI::App& app) {
    auto which = std::make_shared<std::string>();
    CLI::App* s = app.add_subcommand(
        "schema", "print the JSON Schema of scene files or regression suites (for editors)");
    s->add_option("kind", *which, "scene | suite")
        ->required()
        ->check(CLI::IsMember({"scene", "suite"}));
    return {[s] { return s->parsed(); }, [which] { return run_schema(*which); }};
}

} // namespace tumble::app
