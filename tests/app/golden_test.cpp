// Golden images of the built-in scenes (tests/goldens/goldens.json), and the machinery around
// them: a changed frame is caught with actual and diff images written, updates refuse a different
// renderer, re-rendering is bit-identical, and `tumble diff` exits as scripts expect.
// To update the goldens on purpose: scripts/update-goldens.sh (see README).
#include "app/cli_runner.h"
#include "render/png_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace tumble::test {
namespace {

const std::filesystem::path kGoldens = std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests/goldens";

TEST(GoldenImages, EveryListedFrameMatchesItsGolden) {
    const auto dir = scratch_dir();
    const CliResult r = run_tumble(dir, "goldens check '" + (kGoldens / "goldens.json").string() +
                                            "' --artifacts '" + (dir / "artifacts").string() + "'");
    std::printf("%s", r.out.c_str()); // on failure this lists the actual.png and diff.png paths
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

// Copies the committed manifest and goldens into a scratch folder the test may change.
std::filesystem::path copy_goldens(const std::filesystem::path& dir) {
    const auto copy = dir / "goldens";
    std::filesystem::copy(kGoldens, copy, std::filesystem::copy_options::recursive);
    return copy;
}

TEST(GoldenImages, ACorruptedGoldenFailsWithActualAndDiffImages) {
    const auto dir = scratch_dir();
    const auto goldens = copy_goldens(dir);
    render::Image img = render::read_png(goldens / "default_0150.png");
    for (int y = 10; y < 30; ++y) // a 20 x 20 magenta square: 400 pixels, budget is 40
        for (int x = 10; x < 30; ++x) {
            std::uint8_t* p = img.row(y) + 3 * x;
            p[0] = 255, p[1] = 0, p[2] = 255;
        }
    render::write_png(goldens / "default_0150.png", img);
    const CliResult r = run_tumble(dir, "goldens check goldens/goldens.json --artifacts art");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("FAIL   default frame 150"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ok     default frame 0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("art/default_0150.diff.png"), std::string::npos) << r.out;
    const render::Image diff = render::read_png(dir / "art/default_0150.diff.png");
    const std::uint8_t* p = diff.row(20) + 3 * 20;
    EXPECT_EQ(p[0], 255); // red marks the changed square
    EXPECT_LT(p[1], 64);
    EXPECT_TRUE(std::filesystem::exists(dir / "art/default_0150.actual.png"));
}

TEST(GoldenImages, UpdateRefusesGoldensFromAnotherRendererUnlessForced) {
    const auto dir = scratch_dir();
    const auto goldens = copy_goldens(dir);
    std::string manifest = read_text(goldens / "goldens.json");
    const auto at = manifest.find("\"gl_version\": \"");
    ASSERT_NE(at, std::string::npos);
    manifest.insert(at + 15, "another ");
    write_text(goldens / "goldens.json", manifest);
    const std::string before = read_text(goldens / "default_0000.png");
    CliResult r = run_tumble(dir, "goldens update goldens/goldens.json");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(goldens / "default_0000.png"), before);
    // check still runs, and says the renderer differs (exit 0 here: the pixels do match).
    r = run_tumble(dir, "goldens check goldens/goldens.json");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("goldens were made with"), std::string::npos) << r.out;
    r = run_tumble(dir, "goldens update --force goldens/goldens.json");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_text(goldens / "goldens.json").find("another"), std::string::npos);
}

// A scene added to assets/scenes without goldens fails here, saying how to add them.
TEST(GoldenImages, EveryBuiltInSceneHasGoldens) {
    const std::string manifest = read_text(kGoldens / "goldens.json");
    for (const auto& e : std::filesystem::directory_iterator(
             std::filesystem::path(TUMBLE_SOURCE_DIR) / "assets/scenes")) {
        if (e.path().extension() != ".json") continue;
        const std::string name = e.path().stem().string();
        EXPECT_NE(manifest.find("\"scene\": \"" + name + "\""), std::string::npos)
            << "scene " << name << " has no golden images; add them with "
            << "scripts/update-goldens.sh --add-missing (see README, Golden images)";
    }
}

// --add-missing renders goldens for scenes without any and leaves the others alone.
TEST(GoldenImages, AddMissingAddsFirstMiddleAndLastFramesOnly) {
    const auto dir = scratch_dir();
    const auto goldens = copy_goldens(dir);
    nlohmann::json m = nlohmann::json::parse(read_text(goldens / "goldens.json"));
    nlohmann::json kept = nlohmann::json::array();
    for (const auto& image : m["images"])
        if (image["scene"] != "default") kept.push_back(image);
    m["images"] = kept; // as if default.json were a new scene
    write_text(goldens / "goldens.json", m.dump(2));
    for (const auto& e : std::filesystem::directory_iterator(goldens))
        if (e.path().extension() == ".png") std::filesystem::remove(e.path());
    CliResult r = run_tumble(dir, "goldens update goldens/goldens.json --add-missing");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(files_in(goldens), (std::vector<std::string>{"default_0000.png", "default_0300.png",
                                                           "default_0599.png", "goldens.json"}));
    m = nlohmann::json::parse(read_text(goldens / "goldens.json"));
    EXPECT_EQ(m["images"].size(), kept.size() + 3);
    r = run_tumble(dir, "goldens check goldens/goldens.json --scene default");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("3 golden image(s), 0 failed"), std::string::npos) << r.out;
    r = run_tumble(dir, "goldens update goldens/goldens.json --add-missing"); // nothing to do
    EXPECT_NE(r.out.find("every built-in scene has goldens"), std::string::npos) << r.out;
}

TEST(GoldenImages, RenderingTheSameFrameTwiceGivesIdenticalPixels) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_tumble(dir, "render --frame 90 --width 320 --height 180 -o a.png").exit_code, 0);
    ASSERT_EQ(run_tumble(dir, "render --frame 90 --width 320 --height 180 -o b.png").exit_code, 0);
    EXPECT_EQ(render::read_png(dir / "a.png").rgb, render::read_png(dir / "b.png").rgb);
}

TEST(Diff, ExitCodesAndDiffImageForScripts) {
    const auto dir = scratch_dir();
    const auto g = kGoldens;
    CliResult r = run_tumble(dir, "diff '" + (g / "default_0000.png").string() + "' '" +
                                      (g / "default_0000.png").string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("identical"), std::string::npos) << r.out;
    r = run_tumble(dir, "diff '" + (g / "default_0000.png").string() + "' '" +
                            (g / "default_0150.png").string() + "' -o d.png");
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "d.png"));
    r = run_tumble(dir, "diff missing.png '" + (g / "default_0000.png").string() + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("missing.png"), std::string::npos) << r.err;
}

} // namespace
} // namespace tumble::test
