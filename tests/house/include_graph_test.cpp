// The house's one-way dependencies (docs/architecture.md), checked over the include graph of the
// whole source tree: every `#include "..."` of every source and header is held against the table
// below, and no include may climb out of its folder with "../". The build enforces most of this
// too (each library sees only the headers of what it links; tests/house/probes); this test
// covers what an include root cannot: a library's own subfolders (physics/exact,
// physics/scenes), tests and benchmarks, and relative paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Room {
    std::string folder;               // files below it, the longest match wins
    std::vector<std::string> may_see; // include prefixes allowed
    std::vector<std::string> may_not; // prefixes refused even below an allowed one
};

// Lower rooms first; a room may see itself and the rooms it lists, nothing above.
const std::vector<Room> kRooms = {
    {"io", {"io/"}, {}},
    {"physics", {"physics/"}, {"physics/exact/", "physics/scenes/"}},
    {"physics/exact", {"physics/"}, {}},
    {"physics/scenes", {"physics/"}, {}},
    {"render", {"render/", "io/"}, {}},
    {"app/scene", {"app/scene/", "physics/", "render/", "io/"}, {"physics/exact/"}},
    {"app/view", {"app/view/", "app/scene/", "physics/", "render/", "io/"}, {"physics/exact/"}},
    {"app/run",
     {"app/run/", "app/view/", "app/scene/", "physics/", "render/", "io/"},
     {"physics/exact/"}},
    {"app/cluster",
     {"app/cluster/", "app/run/", "app/view/", "app/scene/", "physics/", "render/", "io/"},
     {"physics/exact/"}},
    {"app/gnuplot", {"app/gnuplot/", "io/"}, {}},
    {"app/study", {"app/study/", "app/gnuplot/", "physics/", "io/"}, {}},
    {"app/regression",
     {"app/regression/", "app/run/", "app/scene/", "physics/", "render/", "io/"},
     {"physics/exact/"}},
    {"app/plot",
     {"app/plot/", "app/run/", "app/scene/", "app/gnuplot/", "physics/", "io/"},
     {"physics/exact/"}},
    {"app/python",
     {"app/python/", "app/run/", "app/view/", "app/scene/", "physics/", "render/", "io/"},
     {"physics/exact/"}},
    {"app/cli", {"app/", "physics/", "render/", "io/"}, {"app/python/"}},
    {"tests", {""}, {"bench/"}},
    {"bench", {""}, {"tests/", "app/"}},
    // The render benchmark prepares and draws runs as `tumble render` does (app/run).
    {"bench/render", {""}, {"tests/", "app/cli/", "app/python/"}},
};

const Room* room_of(const std::string& file) {
    const Room* best = nullptr;
    for (const Room& r : kRooms)
        if (file.rfind(r.folder + "/", 0) == 0 && (!best || r.folder.size() > best->folder.size()))
            best = &r;
    return best;
}

bool starts_with_any(const std::string& s, const std::vector<std::string>& prefixes) {
    return std::any_of(prefixes.begin(), prefixes.end(),
                       [&](const std::string& p) { return s.rfind(p, 0) == 0; });
}

// Why `file` (a path from the source root) may not include `header`; empty when it may.
std::string violation(const std::string& file, const std::string& header) {
    if (header.find("..") != std::string::npos) return "climbs out of its folder with ..";
    const Room* room = room_of(file);
    if (!room) return ""; // not in a layered room (e.g. cmake/, scripts/)
    if (header.find('/') == std::string::npos) return ""; // a header beside it (tests' helpers)
    if (starts_with_any(header, room->may_not) || !starts_with_any(header, room->may_see))
        return room->folder + "/ may not see " + header;
    return "";
}

struct Include {
    std::string file, header;
};

std::vector<Include> includes_in_tree(const fs::path& root) {
    static const std::regex quoted(R"re(^\s*#\s*include\s*"([^"]+)")re");
    std::vector<Include> out;
    for (const char* top : {"io", "physics", "render", "app", "tests", "bench"}) {
        for (const auto& e : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = e.path().extension().string();
            if (!e.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
            if (e.path().string().find("/probes/") != std::string::npos) continue; // must fail
            std::ifstream in(e.path());
            std::smatch m;
            for (std::string line; std::getline(in, line);)
                if (std::regex_search(line, m, quoted))
                    out.push_back({fs::relative(e.path(), root).generic_string(), m[1].str()});
        }
    }
    return out;
}

TEST(House, EveryIncludePointsOneWay) {
    const std::vector<Include> all = includes_in_tree(TUMBLE_SOURCE_DIR);
    // The tree has hundreds of includes; far fewer means the walk missed the sources.
    ASSERT_GT(all.size(), 500u);
    int layered = 0;
    for (const Include& inc : all) {
        layered += room_of(inc.file) != nullptr;
        const std::string why = violation(inc.file, inc.header);
        EXPECT_TRUE(why.empty()) << inc.file << " includes \"" << inc.header << "\": " << why;
    }
    EXPECT_EQ(layered, int(all.size())) << "every walked file belongs to a room";
}

// The checker itself: the includes the house forbids are caught, the ones it allows are not.
TEST(House, TheCheckerRefusesBackwardIncludes) {
    EXPECT_FALSE(violation("physics/step.cpp", "render/renderer.h").empty());
    EXPECT_FALSE(violation("physics/step.cpp", "app/scene/scene.h").empty());
    EXPECT_FALSE(violation("physics/step.cpp", "physics/exact/free_rigid_body.h").empty());
    EXPECT_FALSE(violation("render/renderer.cpp", "app/view/camera.h").empty());
    EXPECT_FALSE(violation("render/renderer.cpp", "physics/model.h").empty());
    EXPECT_FALSE(violation("app/scene/scene.h", "app/run/simulation.h").empty());
    EXPECT_FALSE(violation("app/run/still.cpp", "app/cli/failure.h").empty());
    EXPECT_FALSE(violation("app/view/camera.cpp", "app/run/timeline.h").empty());
    EXPECT_FALSE(violation("app/study/runner.cpp", "app/scene/scene.h").empty());
    EXPECT_FALSE(violation("app/regression/suite.cpp", "app/cli/failure.h").empty());
    EXPECT_FALSE(violation("app/regression/suite.cpp", "app/study/study.h").empty());
    EXPECT_FALSE(violation("app/run/still.cpp", "app/regression/suite.h").empty());
    EXPECT_FALSE(violation("app/gnuplot/gnuplot.cpp", "app/plot/figure.h").empty());
    EXPECT_FALSE(violation("app/gnuplot/gnuplot.cpp", "app/study/study.h").empty());
    EXPECT_FALSE(violation("app/plot/figure.cpp", "app/study/report.h").empty());
    EXPECT_FALSE(violation("app/plot/figure.cpp", "app/cli/failure.h").empty());
    EXPECT_FALSE(violation("app/plot/figure.cpp", "app/view/camera.h").empty());
    EXPECT_FALSE(violation("app/run/render_frames.cpp", "app/cluster/checkpoint.h").empty());
    EXPECT_FALSE(violation("app/cluster/video_join.cpp", "app/cli/failure.h").empty());
    EXPECT_FALSE(violation("tests/physics/x_test.cpp", "bench/sphere_rain.h").empty());
    EXPECT_FALSE(violation("bench/x_bench.cpp", "tests/support/measured.h").empty());
    EXPECT_FALSE(violation("render/png_io.cpp", "../app/scene/scene.h").empty());
    EXPECT_FALSE(violation("bench/render/render_measure.cpp", "app/cli/render_setup.h").empty());
    EXPECT_FALSE(violation("bench/render/render_cases.cpp", "tests/support/measured.h").empty());

    EXPECT_EQ(violation("app/run/still.cpp", "app/scene/scene.h"), "");
    EXPECT_EQ(violation("app/cluster/checkpoint_store.cpp", "app/run/simulation.h"), "");
    EXPECT_EQ(violation("app/cli/join_command.cpp", "app/cluster/video_join.h"), "");
    EXPECT_EQ(violation("app/cli/main.cpp", "app/run/interrupt.h"), "");
    EXPECT_EQ(violation("app/regression/suite.cpp", "app/run/frame_source.h"), "");
    EXPECT_EQ(violation("render/png_sink.cpp", "io/atomic_file.h"), "");
    EXPECT_EQ(violation("physics/exact/body_motion.cpp", "physics/model.h"), "");
    EXPECT_EQ(violation("tests/app/cli/x_test.cpp", "app/cli/failure.h"), "");
    EXPECT_EQ(violation("bench/render/render_measure.cpp", "app/run/prepare_run.h"), "");
}

} // namespace
