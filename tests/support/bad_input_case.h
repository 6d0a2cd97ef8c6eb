#pragma once
// Shared by the bad-input tests: a broken scene, made from a valid one by one text replacement,
// and what its error message must contain.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
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

// Writes the case's scene as bad.json in a fresh folder (with the `extra` files, name and text)
// and runs `render` and `simulate` on it: each must exit 2 with `named` and every expected part
// in its message, and leave nothing but the files it was given.
inline void expect_refused(const Case& c, const std::string& named = "bad.json",
                           const std::vector<std::pair<std::string, std::string>>& extra = {}) {
    SCOPED_TRACE(c.name);
    const auto dir = scratch_dir() / c.name;
    std::filesystem::create_directories(dir);
    write_text(dir / "bad.json", c.scene);
    std::vector<std::string> given{"bad.json"};
    for (const auto& [name, text] : extra) {
        write_text(dir / name, text);
        given.push_back(name);
    }
    std::sort(given.begin(), given.end());
    for (const char* cmd : {"render bad.json -o out.mp4", "simulate bad.json -o states.csv"}) {
        SCOPED_TRACE(cmd);
        const CliResult r = run_tumble(dir, cmd);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
        for (const std::string& s : c.expected)
            EXPECT_NE(r.err.find(s), std::string::npos) << s << "\n" << r.err;
        EXPECT_EQ(files_in(dir), given);
    }
}

} // namespace tumble::test
