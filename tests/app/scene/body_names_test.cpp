// with_body_names() puts the scene's names beside each "body N" of a physics message; its hand
// scan is checked against the regular expression \bbody (\d+)\b applied by std::regex here.
#include "app/scene/scene_check.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

namespace tumble::test {
namespace {

// The expected text: each match of \bbody (\d+)\b with an index below names.size() becomes
// `body N "name"`, any other match stays as it was.
std::string by_regex(const std::vector<std::string>& names, const std::string& what) {
    static const std::regex body(R"(\bbody (\d+)\b)");
    std::string out;
    auto last = what.cbegin();
    for (std::sregex_iterator it(what.begin(), what.end(), body), end; it != end; ++it) {
        out.append(last, (*it)[0].first);
        const std::string digits = (*it)[1].str();
        const bool known = digits.size() < 10 && std::stoul(digits) < names.size();
        out += known ? "body " + digits + " \"" + names[std::stoul(digits)] + "\"" : (*it)[0].str();
        last = (*it)[0].second;
    }
    out.append(last, what.cend());
    return out;
}

TEST(BodyNames, EveryStandaloneBodyIndexIsNamedAsTheRegularExpressionFindsIt) {
    const std::vector<std::string> names = {"floor", "ball", "left wall"};
    const std::vector<std::string> messages = {
        "body 1: mass must be positive",
        "body 0 starts interpenetrating body 2 by 5 mm",
        "body 2, body 1 and body 0.",
        "somebody 1 is not a body",       // "somebody": no word boundary before "body"
        "body 12 is out of range",        // an index the scene does not have
        "body 1a and body_1 and body 1_", // no boundary after the digits
        "body  1 (two spaces) and body x",
        "(body 0)[body 1]{body 2}",
        "body 99999999999999999999 is huge",
        "ends with body 2",
        "body ",
        "body",
        "",
        "nobody body 0body 1 body 1",
    };
    for (const std::string& m : messages) {
        SCOPED_TRACE(m);
        EXPECT_EQ(app::with_body_names(names, m), by_regex(names, m));
    }
    // The expectation itself names what it should (so the comparison is not of two no-ops).
    EXPECT_EQ(by_regex(names, "body 0 starts interpenetrating body 2 by 5 mm"),
              "body 0 \"floor\" starts interpenetrating body 2 \"left wall\" by 5 mm");
}

} // namespace
} // namespace tumble::test
