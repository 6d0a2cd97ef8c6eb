// PNG writing and reading: exact round trips with both encoders, conversion of other PNG
// flavours to RGB, errors that name the file, and (on demand) the encoder speed measurement.
#include "render/png_io.h"

#include "test_support.h"

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>

namespace tumble::render {

// Names the parameter in test listings ("GetParam() = libpng").
void PrintTo(PngEncoder encoder, std::ostream* out) {
    *out << to_string(encoder);
}

namespace {

namespace fs = std::filesystem;
using test::fresh_artifact_dir;
using test::list_dir;

// Every byte value in every channel, so a round trip that clamps or rounds anything shows.
Image all_values_image() {
    Image image(256, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 256; ++x) {
            std::uint8_t* p = image.row(y) + 3 * x;
            p[0] = static_cast<std::uint8_t>(x);
            p[1] = static_cast<std::uint8_t>(255 - x);
            p[2] = static_cast<std::uint8_t>((x * 7 + y * 31) & 255);
        }
    }
    return image;
}

class PngRoundTrip : public ::testing::TestWithParam<PngEncoder> {};

TEST_P(PngRoundTrip, ReadsBackBitForBit) {
    const fs::path dir = fresh_artifact_dir();
    for (const Image& image : {all_values_image(), test::rendered_like(160, 90)}) {
        const fs::path path = dir / "round_trip.png";
        write_png(path, image, {GetParam(), 1});
        const Image back = read_png(path);
        EXPECT_EQ(back.width, image.width);
        EXPECT_EQ(back.height, image.height);
        EXPECT_TRUE(back.rgb == image.rgb) << to_string(GetParam());
    }
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"round_trip.png"}); // no temporary left
}

INSTANTIATE_TEST_SUITE_P(Encoders, PngRoundTrip,
                         ::testing::Values(PngEncoder::libpng, PngEncoder::stb),
                         [](const auto& info) {
                             return std::string(info.param == PngEncoder::libpng ? "libpng"
                                                                                 : "stb");
                         });

TEST(PngIo, EveryLevelRoundTrips) {
    const fs::path path = fresh_artifact_dir() / "level.png";
    const Image image = test::rendered_like(64, 48);
    for (int level : {0, 1, 6, 9}) {
        write_png(path, image, {PngEncoder::libpng, level});
        EXPECT_TRUE(read_png(path).rgb == image.rgb) << "level " << level;
    }
}

// Writes a PNG in another pixel format with libpng's simplified API.
void write_other_png(const fs::path& path, std::uint32_t format, int width, int height,
                     const std::vector<std::uint8_t>& pixels) {
    png_image info{};
    info.version = PNG_IMAGE_VERSION;
    info.width = static_cast<png_uint_32>(width);
    info.height = static_cast<png_uint_32>(height);
    info.format = format;
    ASSERT_TRUE(png_image_write_to_file(&info, path.c_str(), 0, pixels.data(), 0, nullptr))
        << info.message;
}

TEST(PngIo, ReadsGrayAsRgb) {
    const fs::path path = fresh_artifact_dir() / "gray.png";
    write_other_png(path, PNG_FORMAT_GRAY, 3, 1, {0, 128, 255});
    const Image image = read_png(path);
    ASSERT_EQ(image.width, 3);
    EXPECT_EQ(image.rgb, (std::vector<std::uint8_t>{0, 0, 0, 128, 128, 128, 255, 255, 255}));
}

TEST(PngIo, ReadsRgbaDroppingAlpha) {
    const fs::path path = fresh_artifact_dir() / "rgba.png";
    write_other_png(path, PNG_FORMAT_RGBA, 2, 1, {10, 20, 30, 255, 40, 50, 60, 0});
    const Image image = read_png(path);
    ASSERT_EQ(image.width, 2);
    EXPECT_EQ(image.rgb, (std::vector<std::uint8_t>{10, 20, 30, 40, 50, 60}));
}

// Expects `call` to throw PngError whose message contains `path`.
template <class Call>
void expect_error_naming(const fs::path& path, Call call) {
    try {
        call();
        ADD_FAILURE() << "no error for " << path;
    } catch (const PngError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
}

TEST(PngIo, ReadErrorsNameTheFile) {
    const fs::path dir = fresh_artifact_dir();
    expect_error_naming(dir / "missing.png", [&] { read_png(dir / "missing.png"); });

    std::ofstream(dir / "text.png") << "not a png at all";
    expect_error_naming(dir / "text.png", [&] { read_png(dir / "text.png"); });

    // A real PNG cut in half: the signature is fine, the data is not.
    write_png(dir / "whole.png", test::rendered_like(64, 48));
    std::ifstream whole(dir / "whole.png", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(whole)), {});
    std::ofstream(dir / "cut.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    expect_error_naming(dir / "cut.png", [&] { read_png(dir / "cut.png"); });
}

TEST(PngIo, WriteErrorsNameTheFileAndLeaveNothing) {
    const fs::path dir = fresh_artifact_dir();
    const fs::path path = dir / "no_such_dir" / "x.png";
    expect_error_naming(path, [&] { write_png(path, test::rendered_like(8, 8)); });
    expect_error_naming(dir / "empty.png", [&] { write_png(dir / "empty.png", Image()); });
    EXPECT_TRUE(list_dir(dir).empty());
}

// A full disk (simulated with a file size limit) fails the write with a message naming the file
// and leaves neither a partial file nor a temporary one behind.
TEST(PngIo, FullDiskFailsCleanly) {
    const fs::path dir = fresh_artifact_dir();
    const Image big = test::noise(256, 256, 1); // ~192 KiB, incompressible
    for (PngEncoder encoder : {PngEncoder::libpng, PngEncoder::stb}) {
        const test::FileSizeLimit limit(64 * 1024);
        expect_error_naming(dir / "full.png", [&] { write_png(dir / "full.png", big, {encoder}); });
    }
    EXPECT_TRUE(list_dir(dir).empty());
}

TEST(PngIo, WriteReplacesAnExistingFile) {
    const fs::path path = fresh_artifact_dir() / "replace.png";
    write_png(path, test::rendered_like(32, 24));
    const Image second = test::rendered_like(16, 12);
    write_png(path, second);
    EXPECT_TRUE(read_png(path).rgb == second.rgb);
}

// The measurement behind the default encoder (run it with --gtest_also_run_disabled_tests
// --gtest_filter='*MeasureWriters'): frames per second of each writer at 1280x720, including
// creating, writing and renaming the file, median of 15 runs.
TEST(PngIo, DISABLED_MeasureWriters) {
    const fs::path path = fresh_artifact_dir() / "speed.png";
    const Image image = test::rendered_like(1280, 720);
    const struct {
        const char* name;
        PngWriteOptions options;
    } writers[] = {{"stb_image_write, stb default level 8", {PngEncoder::stb, 8}},
                   {"stb_image_write, level 1", {PngEncoder::stb, 1}},
                   {"libpng, level 1, sub filter (default)", {PngEncoder::libpng, 1}},
                   {"libpng, level 6, sub filter", {PngEncoder::libpng, 6}}};
    for (const auto& writer : writers) {
        std::vector<double> fps;
        for (int run = 0; run < 15; ++run) {
            const auto start = std::chrono::steady_clock::now();
            write_png(path, image, writer.options);
            const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
            fps.push_back(1 / took.count());
        }
        std::sort(fps.begin(), fps.end());
        std::printf("%-40s median %6.1f fps, %7.1f KiB\n", writer.name, fps[fps.size() / 2],
                    static_cast<double>(fs::file_size(path)) / 1024);
    }
}

} // namespace
} // namespace tumble::render
