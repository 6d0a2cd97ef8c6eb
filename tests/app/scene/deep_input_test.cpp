// Values no scene needs, however deep or long, get a short message and exit 2: nothing walks a
// deeply nested value recursively (the stack would overflow) and no message quotes a whole value.
#include "support/bad_input_case.h"
#include "support/cli_runner.h"
#include "support/measured.h"

#include <gtest/gtest.h>

namespace tumble::test {
namespace {

// A minimal scene with `value` at "title", a body's "name" or "world.integrator".
std::string scene_with(const std::string& where, const std::string& value) {
    const std::string title = where == "title" ? value : "\"t\"";
    const std::string name = where == "name" ? value : "\"ball\"";
    const std::string integrator = where == "integrator" ? value : "\"rk4\"";
    return "{\"format_version\": 1, \"title\": " + title +
           ",\n \"world\": {\"duration\": 0.1, \"integrator\": " + integrator +
           "},\n \"bodies\": [{\"name\": " + name +
           ", \"shape\": {\"type\": \"sphere\", \"radius\": 0.1}}]}";
}

std::string nested_arrays(int depth) {
    return std::string(std::size_t(depth), '[') + std::string(std::size_t(depth), ']');
}

std::string nested_objects(int depth) {
    std::string out;
    for (int k = 0; k < depth; ++k) out += "{\"a\": ";
    return out + "0" + std::string(std::size_t(depth), '}');
}

// Runs `simulate` on `scene`; exit 2, a message under 1 KB naming the file and each of `expected`.
void expect_short_refusal(const std::string& scene, const std::vector<std::string>& expected) {
    const auto dir = scratch_dir();
    write_text(dir / "bad.json", scene);
    const CliResult r = run_tumble(dir, "simulate bad.json -o states.csv");
    EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 2000);
    EXPECT_LT(r.err.size(), 1024u) << r.err.substr(0, 2000);
    TUMBLE_MEASURED(r.err.size(), 1024u);
    EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err.substr(0, 2000);
    for (const std::string& s : expected)
        EXPECT_NE(r.err.find(s), std::string::npos) << s << "\n" << r.err.substr(0, 2000);
    EXPECT_EQ(files_in(dir), std::vector<std::string>{"bad.json"});
}

TEST(DeepInput, ValuesNestedFiftyThousandDeepWhereAStringIsExpectedAreRefusedShortly) {
    for (const char* where : {"title", "name", "integrator"}) {
        SCOPED_TRACE(where);
        expect_short_refusal(scene_with(where, nested_arrays(50000)),
                             {"bad.json:", "nested deeper than 256 levels"});
        expect_short_refusal(scene_with(where, nested_objects(50000)),
                             {"bad.json:", "nested deeper than 256 levels"});
    }
}

TEST(DeepInput, TheNestingLimitNamesLineAndColumnOfTheFirstBracketTooDeep) {
    // Line 1 is `{"format_version": 1, "title": ` (31 characters): the title's first '[' is at
    // column 32, and its 256th '[' opens level 257 (the scene object is level 1).
    expect_short_refusal(scene_with("title", nested_arrays(100000)), {"bad.json:1:287:"});
    // Brackets inside strings are text, not nesting.
    const std::string brackets = "\"" + std::string(1000, '[') + "\"";
    const auto dir = scratch_dir();
    write_text(dir / "ok.json", scene_with("title", brackets));
    EXPECT_EQ(run_tumble(dir, "simulate ok.json -o states.csv -q").exit_code, 0);
}

TEST(DeepInput, ValuesUnderTheLimitAreDescribedByTypeNotPrinted) {
    expect_short_refusal(scene_with("title", nested_arrays(200)),
                         {"/title", "expected a string, got an array of 1 element"});
    expect_short_refusal(scene_with("name", nested_objects(200)),
                         {"/bodies/0/name", "expected a string, got an object with 1 key"});
}

TEST(DeepInput, AMillionElementArrayAsTitleIsDescribedByItsSize) {
    std::string array = "[0";
    for (int k = 1; k < 1000000; ++k) array += ",0";
    expect_short_refusal(scene_with("title", array + "]"),
                         {"/title", "expected a string, got an array of 1000000 elements"});
}

TEST(DeepInput, LongStringsAreQuotedCutToAnExcerpt) {
    const std::string name = "\"" + std::string(1000000, 'v') + "\"";
    expect_short_refusal(scene_with("integrator", name),
                         {"/world/integrator", "unknown integrator \"vvvv",
                          "... (a string of 1000000 bytes)", "valid integrators: "});
    expect_short_refusal(replace(scene_with("title", "\"t\""), "\"title\"", name),
                         {"unknown field \"vvv", "fields allowed here: "});
}

} // namespace
} // namespace tumble::test
