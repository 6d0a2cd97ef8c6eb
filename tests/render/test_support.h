#pragma once
// Helpers for the render tests: synthetic pictures (no renderer needed, fully deterministic) and
// a clean scratch folder per test.
#include "render/image.h"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tumble::render::test {

inline std::uint8_t to_byte(double v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}

// Fraction (0..1) of pixel (x, y) covered by the disk at (cx, cy) of radius r, from a 4x4 grid
// of samples: the anti-aliased coverage a renderer with 16x MSAA would produce.
inline double disk_coverage(int x, int y, double cx, double cy, double r) {
    int inside = 0;
    for (int sy = 0; sy < 4; ++sy) {
        for (int sx = 0; sx < 4; ++sx) {
            const double px = x + (sx + 0.5) / 4 - cx, py = y + (sy + 0.5) / 4 - cy;
            inside += px * px + py * py <= r * r;
        }
    }
    return inside / 16.0;
}

// Looks like a Tumble frame: a sky gradient over a perspective checkerboard floor, a few shaded
// balls with anti-aliased edges (moved right by `shift_x` pixels) and a flat box. Smooth areas,
// fine detail and sharp edges: the mix that decides how fast and how well PNG encoders do.
inline Image rendered_like(int width, int height, double shift_x = 0) {
    Image image(width, height);
    const int horizon = height * 3 / 5;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.row(y) + 3 * x;
            const double t = static_cast<double>(y) / height;
            const double u = static_cast<double>(x) / width;
            if (y < horizon) { // sky: blue to pale towards the horizon, lighter towards the sun
                const double sun = 40 * (1 - std::abs(u - 0.7));
                p[0] = to_byte(90 + 120 * t + sun), p[1] = to_byte(140 + 90 * t + sun);
                p[2] = to_byte(230 + sun / 4);
            } else { // floor: a checkerboard in perspective, darker with distance
                const double d = static_cast<double>(y - horizon + 1) / (height - horizon);
                const double depth = 1 / d, across = (u - 0.5) * depth;
                const bool dark = (static_cast<int>(std::floor(depth * 4)) +
                                   static_cast<int>(std::floor(across * 8))) %
                                  2;
                const double lit = (dark ? 90 : 170) * (0.55 + 0.45 * d) + 20 * (1 - u);
                p[0] = p[1] = to_byte(lit), p[2] = to_byte(lit + 8);
            }
        }
    }
    const struct {
        double cx, cy, r;
        std::uint8_t rgb[3];
    } balls[] = {{0.25, 0.55, 0.12, {220, 60, 50}},
                 {0.55, 0.62, 0.09, {60, 180, 90}},
                 {0.78, 0.5, 0.15, {240, 200, 60}}};
    for (const auto& b : balls) {
        const double cx = b.cx * width + shift_x, cy = b.cy * height, r = b.r * height;
        for (int y = std::max(0, int(cy - r - 2)); y < std::min(height, int(cy + r + 2)); ++y) {
            for (int x = std::max(0, int(cx - r - 2)); x < std::min(width, int(cx + r + 2)); ++x) {
                const double cover = disk_coverage(x, y, cx, cy, r);
                if (cover == 0) continue;
                // Lambert shading from a light up and to the left.
                const double nx = (x - cx) / r, ny = (y - cy) / r;
                const double nz = std::sqrt(std::max(0.0, 1 - nx * nx - ny * ny));
                const double shade = 0.25 + 0.75 * std::max(0.0, -0.4 * nx - 0.5 * ny + 0.77 * nz);
                std::uint8_t* p = image.row(y) + 3 * x;
                for (int c = 0; c < 3; ++c)
                    p[c] = to_byte(p[c] * (1 - cover) + b.rgb[c] * shade * cover);
            }
        }
    }
    for (int y = height * 7 / 10; y < height * 17 / 20; ++y) { // a flat box on the floor
        for (int x = width * 2 / 5; x < width * 9 / 20; ++x) {
            std::uint8_t* p = image.row(y) + 3 * x;
            p[0] = 150, p[1] = 100, p[2] = 200;
        }
    }
    return image;
}

// An empty folder for the running test: TUMBLE_TEST_ARTIFACTS/<Suite>.<Test>/, cleared first.
inline std::filesystem::path fresh_artifact_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::path(TUMBLE_TEST_ARTIFACTS) /
                                      (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// File names in `dir`, sorted, hidden (temporary) ones included.
inline std::vector<std::string> list_dir(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

// While alive, files of this process cannot grow past `bytes`: writes beyond fail with EFBIG,
// the way a full disk fails them with ENOSPC. (SIGXFSZ, which would kill the process, is
// ignored meanwhile.)
class FileSizeLimit {
  public:
    explicit FileSizeLimit(rlim_t bytes) {
        previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
        getrlimit(RLIMIT_FSIZE, &previous_);
        rlimit limit = previous_;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &previous_);
        std::signal(SIGXFSZ, previous_handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

  private:
    rlimit previous_{};
    void (*previous_handler_)(int) = nullptr;
};

// Pseudo-random pixels: incompressible, so encoders produce large files.
inline Image noise(int width, int height, std::uint32_t seed) {
    Image image(width, height);
    for (std::uint8_t& byte : image.rgb) {
        seed = seed * 1664525u + 1013904223u; // a linear congruential generator
        byte = static_cast<std::uint8_t>(seed >> 24);
    }
    return image;
}

} // namespace tumble::render::test
