#pragma once
// Shared by the bad-input tests: a broken scene, made from a valid one by one text replacement,
// and what its error message must contain.
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tumble::test {

// `s` with the first occurrence of `from` replaced by `to` (the test fails if there is none).
inline std::string replace(std::string s, const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
}

struct Case {
    const char* name;
    std::string scene;
    std::vector<std::string> expected; // substrings of stderr, besides the file name
};

} // namespace tumble::test
