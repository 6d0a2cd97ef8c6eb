// OBJ files of mesh bodies: a "v" line that is not 3 (or 4) finite numbers, or an "f" line whose
// indices are not integers naming vertices of the file, is bad input (exit 2) naming the scene's
// JSON path, the OBJ file and its line. tinyobjloader alone reads such numbers as 0.
#include "support/bad_input_case.h"
#include "support/cli_runner.h"

#include <gtest/gtest.h>

namespace tumble::test {
namespace {

const char* kScene = R"({"format_version": 1, "world": {"duration": 0.1},
  "bodies": [{"name": "cube", "shape": {"type": "mesh", "file": "cube.obj"}}]})";

// A closed unit cube: vertex 1 at the origin (line 2), faces from line 10.
const char* kCube = "# unit cube\n"
                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

CliResult simulate_with(const std::filesystem::path& dir, const std::string& obj) {
    write_text(dir / "s.json", kScene);
    write_text(dir / "cube.obj", obj);
    return run_tumble(dir, "simulate s.json -o states.csv -q");
}

TEST(ObjInput, NumbersThatDoNotParseAreRefusedNamingFileAndLine) {
    // Each of these read as the origin before (or a face tinyobjloader guessed at), and the cube
    // loaded.
    const std::vector<Case> cases = {
        {"nan", replace(kCube, "v 0 0 0", "v nan 0 0"), {"cube.obj:2:", "\"nan\""}},
        {"word", replace(kCube, "v 0 0 0", "v abc 0 0"), {"cube.obj:2:", "\"abc\""}},
        {"overflow", replace(kCube, "v 0 0 0", "v 1e999 0 0"), {"cube.obj:2:", "\"1e999\""}},
        {"trailing", replace(kCube, "v 0 0 0", "v 0 0 0x"), {"cube.obj:2:", "\"0x\""}},
        {"two_numbers", replace(kCube, "v 0 0 0", "v 0 0"), {"cube.obj:2:", "got 2"}},
        {"face_word", replace(kCube, "f 4 1 5 8", "f 4 1x 5 8"), {"cube.obj:15:", "\"1x\""}},
        {"face_tail", replace(kCube, "f 4 1 5 8", "f 4 1 5 8x"), {"cube.obj:15:", "\"8x\""}},
        {"face_zero", replace(kCube, "f 4 1 5 8", "f 4 1 5 0"), {"cube.obj:15:", "\"0\""}},
        {"face_range", replace(kCube, "f 4 1 5 8", "f 4 1 5 9"), {"cube.obj:15:", "out of range"}},
        {"face_back", replace(kCube, "f 4 1 5 8", "f 4 1 5 -9"), {"cube.obj:15:", "out of range"}},
        {"face_parts", replace(kCube, "f 4 1 5 8", "f 4 1/a 5 8"), {"cube.obj:15:", "\"1/a\""}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const auto dir = scratch_dir() / c.name;
        std::filesystem::create_directories(dir);
        const CliResult r = simulate_with(dir, c.scene);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find("s.json: /bodies/0/shape/file: "), std::string::npos) << r.err;
        for (const std::string& s : c.expected)
            EXPECT_NE(r.err.find(s), std::string::npos) << s << "\n" << r.err;
        EXPECT_EQ(files_in(dir), (std::vector<std::string>{"cube.obj", "s.json"}));
    }
}

TEST(ObjInput, EveryFormOfAValidVertexAndFaceStillLoads) {
    // Weights, colours, comments, CRLF, v/vt/vn corners and indices counted back from the end.
    std::string obj = replace(kCube, "v 0 0 0\n", "v 0 0 0 1\r\n");
    obj = replace(obj, "v 1 0 0\n", "v 1 0 0 0.5 0.5 0.5 # a coloured corner\n");
    obj = replace(obj, "f 1 4 3 2", "vt 0 0\nvn 0 0 -1\nf 1/1/1 4/1/1 3//1 2/1");
    obj = replace(obj, "f 4 1 5 8", "f -5 -8 -4 -1");
    const CliResult r = simulate_with(scratch_dir(), obj);
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

} // namespace
} // namespace tumble::test
