// Inputs that would make Tumble allocate without bound are refused before anything is allocated
// (README, "What Tumble promises"): a scene, OBJ or manifest file over 256 MiB, an input that is
// a FIFO (reading it would wait forever), a frame over 7680x4320, and a PNG whose header claims
// more than 64 Mpx. Every run is bounded by `timeout`, so a regression fails instead of hanging.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace tumble::test {
namespace {

namespace fs = std::filesystem;

// A file of `bytes` that takes no disk space (a hole): the size check must come before reading.
void sparse_file(const fs::path& p, std::uintmax_t bytes) {
    std::ofstream(p) << "{";
    fs::resize_file(p, bytes);
}

CliResult run_bounded(const fs::path& dir, const std::string& args) {
    return run_shell(dir, "timeout 60 \"$TUMBLE\" " + args);
}

void expect_refused(const CliResult& r, const std::string& message) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

TEST(MemoryBounds, InputFilesOver256MiBAreRefusedUnread) {
    const auto dir = scratch_dir();
    sparse_file(dir / "big.json", (std::uintmax_t{256} << 20) + 1);
    expect_refused(run_bounded(dir, "explain big.json"),
                   "big.json: file: the scene is 256.0 MiB; Tumble reads at most 256.0 MiB");
    sparse_file(dir / "suite.json", std::uintmax_t{300} << 20);
    expect_refused(run_bounded(dir, "test suite.json"), "the suite is 300.0 MiB");
    sparse_file(dir / "huge.obj", std::uintmax_t{1} << 30);
    write_text(dir / "mesh.json", R"({"format_version": 1, "bodies": [
        {"name": "m", "shape": {"type": "mesh", "file": "huge.obj"}}]})");
    expect_refused(run_bounded(dir, "explain mesh.json"), "the OBJ mesh is 1024.0 MiB");
}

TEST(MemoryBounds, AnInputThatIsAFifoIsRefusedWithoutWaiting) {
    const auto dir = scratch_dir();
    ASSERT_EQ(mkfifo((dir / "pipe.obj").c_str(), 0600), 0);
    write_text(dir / "mesh.json", R"({"format_version": 1, "bodies": [
        {"name": "m", "shape": {"type": "mesh", "file": "pipe.obj"}}]})");
    expect_refused(run_bounded(dir, "explain mesh.json"), "the OBJ mesh is not a regular file");
}

TEST(MemoryBounds, FramesOver8kUhdAreRefusedBeforeDrawing) {
    const auto dir = scratch_dir();
    expect_refused(run_bounded(dir, "render --frame 0 --width 100000 --height 100000 -o x.png"),
                   "expected 16x16 to 7680x4320 pixels");
    expect_refused(run_bounded(dir, "render --width 7681 --height 16 -o x.mp4"), "7681x16");
    write_text(dir / "wide.json", R"({"format_version": 1, "render": {"width": 7681},
        "bodies": [{"name": "b", "shape": {"type": "sphere", "radius": 1}}]})");
    expect_refused(run_bounded(dir, "explain wide.json"), "/render/width");
    EXPECT_TRUE(files_in(dir) == std::vector<std::string>{"wide.json"});
}

// CRC-32 of PNG chunks (ISO 3309, as PNG's specification gives it).
std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t c = 0xffffffffu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

std::string big_endian(std::uint32_t v) {
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
    return big_endian(std::uint32_t(data.size())) + type + data + big_endian(crc32(type + data));
}

// A valid PNG signature and header declaring 10000 x 10000 RGB pixels (300 MB decoded; stb_image
// alone would allocate that, refusing only above 1 GB), and no pixels.
std::string png_claiming_10000_squared() {
    const std::string ihdr =
        big_endian(10000) + big_endian(10000) + std::string("\x08\x02\0\0\0", 5);
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IEND", "");
}

TEST(MemoryBounds, APngClaimingMoreThan64MpxIsRefusedBeforeItsPixelsAreAllocated) {
    const auto dir = scratch_dir();
    write_text(dir / "claim.png", png_claiming_10000_squared());
    ASSERT_EQ(run_tumble(dir, "render --frame 0 --width 64 --height 48 -o small.png -q").exit_code,
              0);
    const CliResult r = run_bounded(dir, "diff claim.png small.png");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("'claim.png' is 10000x10000 pixels; Tumble reads PNGs of at most 64 Mpx"),
              std::string::npos)
        << r.err;
}

} // namespace
} // namespace tumble::test
