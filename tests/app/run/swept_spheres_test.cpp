// camera.auto's record of the motion (app/run/swept_spheres.h) is bounded, and what it drops
// cannot change the camera: every quantity the fit reads, the largest linear functional of the
// spheres' side points in the two view planes and the extreme slope of those points seen from any
// eye in front of them, is the same over the kept samples as over all of them. Checked here by
// brute force over random motion, and the bound on memory for motion without end.
#include "app/run/swept_spheres.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tumble::app {
namespace {

const ViewAxes kAxes{glm::normalize(glm::dvec3(1, 1, 0)), glm::dvec3(0, 0, 1),
                     glm::normalize(glm::dvec3(1, -1, 0))};

// The four side points of a sample in the plane of `axis` and d (swept_spheres.h), and the
// extremes of what the fit computes from them for one eye (c, D) and functional slope k.
struct Extremes {
    double functional = -INFINITY, slope_lo = INFINITY, slope_hi = -INFINITY;
};

Extremes extremes(const std::vector<SweptSample>& samples, const glm::dvec3& axis, double c,
                  double eye, double k) {
    Extremes e;
    for (const SweptSample& s : samples) {
        const double a = glm::dot(s.x, axis), b = glm::dot(s.x, kAxes.d), r = s.radius;
        // fit_distance: b + R + (|a - c| + R) k, as the largest of the lifted points' functionals
        e.functional = std::max(e.functional, b + r + (std::abs(a - c) + r) * k);
        // centring: (a -+ R - c) / (D - b), the eye at distance D along d
        e.slope_lo = std::min(e.slope_lo, (a - r - c) / (eye - b));
        e.slope_hi = std::max(e.slope_hi, (a + r - c) / (eye - b));
    }
    return e;
}

TEST(SweptSpheres, PruningKeepsEveryExtremeTheCameraFitReads) {
    std::mt19937 rng(11);
    std::normal_distribution<double> n(0.0, 1.0);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<SweptSample> all;
    SweptSpheres swept(kAxes, 256); // pruned many times over 20,000 samples
    for (int i = 0; i < 20000; ++i) {
        // bodies bouncing about in a 4 x 4 x 2 m box, radii 5 to 30 cm
        const SweptSample s{glm::dvec3(4 * u(rng) - 2, 4 * u(rng) - 2, 2 * u(rng)) +
                                0.1 * glm::dvec3(n(rng), n(rng), n(rng)),
                            0.05 + 0.25 * u(rng)};
        all.push_back(s);
        swept.add(s.x, s.radius);
    }
    ASSERT_FALSE(swept.boxed());
    EXPECT_LT(swept.samples().size(), 256u);
    std::printf("[measured] kept %zu of %zu samples\n", swept.samples().size(), all.size());
    int compared = 0;
    for (const glm::dvec3& axis : {kAxes.r, kAxes.u})
        for (int trial = 0; trial < 200; ++trial) {
            const double c = 2 * n(rng), eye = 8 + 20 * u(rng), k = 0.2 + 3 * u(rng);
            const Extremes want = extremes(all, axis, c, eye, k);
            const Extremes got = extremes(swept.samples(), axis, c, eye, k);
            EXPECT_EQ(got.functional, want.functional);
            EXPECT_EQ(got.slope_lo, want.slope_lo);
            EXPECT_EQ(got.slope_hi, want.slope_hi);
            ++compared;
        }
    EXPECT_EQ(compared, 400);
}

// A body circling for ever: every sample is on the outline, so the record cannot stay exact in
// bounded memory; it falls back to the box of every sphere, which still holds them all.
TEST(SweptSpheres, MotionWithoutEndIsBoundedAndStillInsideTheBox) {
    SweptSpheres swept(kAxes, 256);
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < 100000; ++i) {
        const double t = 0.01 * std::sqrt(2.0) * i; // never the same angle twice
        const glm::dvec3 x(std::cos(t), std::sin(t), 0.5);
        swept.add(x, 0.1);
        lo = std::min(lo, x.x - 0.1), hi = std::max(hi, x.x + 0.1);
        ASSERT_LE(swept.samples().size(), 256u);
    }
    EXPECT_TRUE(swept.boxed());
    // The kept spheres reach as far as the motion did, on every axis
    double kept_lo = INFINITY, kept_hi = -INFINITY;
    for (const SweptSample& s : swept.samples())
        kept_lo = std::min(kept_lo, s.x.x - s.radius),
        kept_hi = std::max(kept_hi, s.x.x + s.radius);
    EXPECT_LE(kept_lo, lo);
    EXPECT_GE(kept_hi, hi);
}

} // namespace
} // namespace tumble::app
