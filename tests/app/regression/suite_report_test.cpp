// What `tumble test` hands to CI and to people: JUnit XML that validates against the schema CI
// tools read (xmllint, tests/data/junit.xsd), the same results for any --jobs, and an HTML
// report that a real browser (Debian's chromium, headless) draws with the failure first.
#include "app/regression/suite_support.h"

#include <regex>
#include <set>

namespace tumble::test {
namespace {

const std::filesystem::path kJunitSchema =
    std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests/data/junit.xsd";

// Checks of four scenes, one of them broken: default_0150, which is not first in the suite.
const char* kSome = "--filter 'default*' --filter 'tossed_book*' --filter 'newtons_cradle*' "
                    "--filter spinning_top_states";

std::filesystem::path broken_goldens(const std::filesystem::path& dir) {
    const auto goldens = copy_goldens(dir);
    paint_square(goldens / "default_0150.png", 10, 10, 20);
    return goldens;
}

CliResult xmllint(const std::filesystem::path& dir, const std::string& file) {
    return run_shell(dir, "xmllint --noout --schema '" + kJunitSchema.string() + "' " + file);
}

TEST(RegressionReport, JUnitValidatesAgainstTheSchemaCiToolsRead) {
    const auto dir = scratch_dir();
    broken_goldens(dir);
    const CliResult r = run_tumble(dir, std::string("test goldens/suite.json ") + kSome +
                                            " --junit out/junit.xml --report out/report");
    ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
    const CliResult valid = xmllint(dir, "out/junit.xml");
    EXPECT_EQ(valid.exit_code, 0) << valid.err;
    const std::string xml = read_text(dir / "out/junit.xml");
    const auto count = [&](const std::string& part) {
        std::size_t n = 0;
        for (auto at = xml.find(part); at != std::string::npos; at = xml.find(part, at + 1)) ++n;
        return n;
    };
    EXPECT_EQ(count("<testcase "), 13u); // 4 of default, tossed_book, newtons_cradle; 1 more
    EXPECT_EQ(count("<failure "), 1u);
    EXPECT_TRUE(contains(xml, "<testsuites name=\"Tumble: the built-in scenes\" tests=\"13\" "
                              "failures=\"1\" errors=\"0\""))
        << xml;
    EXPECT_TRUE(contains(xml, "<failure message=\"")) << xml;
    EXPECT_TRUE(
        std::regex_search(xml, std::regex("message=\"[0-9]+ pixels differ \\(allowed 40\\)")))
        << xml;
    EXPECT_TRUE(contains(xml, "[[ATTACHMENT|out/report/images/default_0150.diff.png]]")) << xml;
    // The schema is not a rubber stamp: a testsuite without its count of tests is refused.
    write_text(dir / "bad.xml", std::regex_replace(xml, std::regex(" tests=\"4\""), "",
                                                   std::regex_constants::format_first_only));
    EXPECT_NE(xmllint(dir, "bad.xml").exit_code, 0);
}

// Everything but the times is the same with 1 job and with 3.
TEST(RegressionReport, ResultsAreTheSameForAnyNumberOfJobs) {
    const auto dir = scratch_dir();
    broken_goldens(dir);
    std::string out[2], junit[2];
    for (int k = 0; k < 2; ++k) {
        const std::string run = k == 0 ? "a" : "b";
        const CliResult r =
            run_tumble(dir, std::string("test goldens/suite.json ") + kSome + " --jobs " +
                                (k == 0 ? "1" : "3") + " --junit " + run + ".xml --report " + run);
        EXPECT_EQ(r.exit_code, 1) << r.err;
        out[k] = std::regex_replace(r.out, std::regex("\\d+ job\\(s\\)|report: \\w+/"), "");
        junit[k] =
            std::regex_replace(read_text(dir / (run + ".xml")),
                               std::regex(" (time|timestamp)=\"[^\"]*\"|\\|" + run + "/"), "");
    }
    EXPECT_EQ(out[0], out[1]);
    EXPECT_EQ(junit[0], junit[1]);
    const std::vector<std::string> images = files_in(dir / "a/images");
    EXPECT_EQ(images, files_in(dir / "b/images"));
    EXPECT_EQ(images.size(), 11u); // 8 drawings that passed; golden, drawing, diff of the failure
    for (const std::string& f : images)
        EXPECT_EQ(read_text(dir / "a/images" / f), read_text(dir / "b/images" / f)) << f;
}

// Pixels of a screenshot that differ from its top-left colour: a blank page has none.
std::size_t inked_pixels(const render::Image& shot) {
    std::size_t n = 0;
    for (int y = 0; y < shot.height; ++y)
        for (int x = 0; x < shot.width; ++x)
            n += !std::equal(shot.row(y) + 3 * x, shot.row(y) + 3 * x + 3, shot.row(0));
    return n;
}

TEST(RegressionReport, ChromiumDrawsTheReportWithTheFailureFirst) {
    const auto dir = scratch_dir();
    broken_goldens(dir);
    ASSERT_EQ(run_shell(dir, "command -v chromium").exit_code, 0)
        << "the report's browser test needs Debian's chromium: scripts/setup.sh installs it";
    ASSERT_EQ(run_tumble(dir, std::string("test goldens/suite.json ") + kSome + " --report rep")
                  .exit_code,
              1);
    const std::string url = "file://" + (dir / "rep/index.html").string();
    // A profile of its own: nothing read from or written to the user's ~/.config/chromium.
    const std::string chromium = "chromium --headless --no-sandbox --disable-gpu --no-first-run "
                                 "--disable-extensions --user-data-dir='" +
                                 (dir / "profile").string() + "' ";
    CliResult r = run_shell(dir, chromium + "--window-size=1280,1600 --screenshot=" +
                                     (dir / "shot.png").string() + " '" + url + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const render::Image shot = render::read_png(dir / "shot.png");
    EXPECT_EQ(shot.width, 1280);
    EXPECT_GT(inked_pixels(shot), std::size_t(shot.width) * shot.height / 10); // not blank
    r = run_shell(dir, chromium + "--dump-dom '" + url + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::smatch first;
    ASSERT_TRUE(std::regex_search(r.out, first, std::regex("data-check=\"([^\"]+)\"")));
    EXPECT_EQ(first[1], "default_0150"); // the failure, before default_0000 which comes first
    EXPECT_TRUE(contains(r.out, "data-status=\"failed\"")) << r.out.substr(0, 2000);
    // The script ran: the slider's label was filled in.
    EXPECT_TRUE(contains(r.out, "golden | this run at 50%"));
    EXPECT_TRUE(contains(r.out, "tumble test goldens/suite.json --update --filter default_0150"));
    // Self-contained: nothing fetched from a network; every image it shows is in the folder.
    const std::string html = read_text(dir / "rep/index.html");
    EXPECT_FALSE(std::regex_search(html, std::regex("(src|href)=\"(https?:)?//")));
    const std::regex img("src=\"(images/[^\"]+)\"");
    int shown = 0;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), img);
         it != std::sregex_iterator(); ++it, ++shown)
        EXPECT_TRUE(std::filesystem::exists(dir / "rep" / (*it)[1].str())) << (*it)[1];
    EXPECT_GT(shown, 10);
}

} // namespace
} // namespace tumble::test
