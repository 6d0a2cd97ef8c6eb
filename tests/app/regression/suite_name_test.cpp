// The loader's test of a check's name (is_check_name) against the pattern the schema gives
// editors (kNamePattern), matched here by std::regex: the two must accept the same names.
#include "app/regression/suite_fields.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

namespace tumble::test {
namespace {

namespace fields = app::suite_fields;

TEST(CheckNames, TheLoadersTestAcceptsWhatTheSchemasPatternAccepts) {
    const std::regex pattern(fields::kNamePattern);
    const std::vector<std::string> names = {"ball_drop",
                                            "ball-drop.v2",
                                            "A",
                                            "0",
                                            "9lives",
                                            "x.",
                                            "a-",
                                            "default_states",
                                            "",
                                            "_x",
                                            ".hidden",
                                            "-x",
                                            "a b",
                                            "a/b",
                                            "../x",
                                            "a\\\\b",
                                            "caf\xc3\xa9",
                                            "tab\there",
                                            "a:b",
                                            "a*",
                                            "line\nbreak",
                                            "Z_9.-",
                                            std::string("nul\0in", 6)};
    int accepted = 0;
    for (const std::string& n : names) {
        SCOPED_TRACE(n);
        const bool expected = std::regex_match(n, pattern);
        EXPECT_EQ(fields::is_check_name(n), expected);
        accepted += expected;
    }
    // Both kinds are exercised: the list is not all accepted or all refused.
    EXPECT_EQ(accepted, 9);
}

// Every printable ASCII character, first and later in a name, as the pattern decides.
TEST(CheckNames, EachAsciiCharacterAsThePatternDecides) {
    const std::regex pattern(fields::kNamePattern);
    for (int c = 1; c < 128; ++c) {
        const std::string first(1, char(c)), later = "a" + first;
        EXPECT_EQ(fields::is_check_name(first), std::regex_match(first, pattern)) << c;
        EXPECT_EQ(fields::is_check_name(later), std::regex_match(later, pattern)) << c;
    }
}

} // namespace
} // namespace tumble::test
