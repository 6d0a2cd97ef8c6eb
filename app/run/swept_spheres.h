#pragma once
// What camera.auto must keep in view (auto_camera.h): every moving body's bounding sphere at every
// frame of the run, in memory bounded by kCap samples whatever the duration (a mistyped duration
// of 1e12 s must not fill the machine).
//
// The camera is fitted in two planes seen from the camera: (right, towards) and (up, towards).
// In each, a sample (centre x, radius R) at a = x.right (or x.up), b = x.towards enters the fit
// only through four points: (a - R, b) and (a + R, b), whose slopes from the eye bound the frame's
// extent, and (a - R, b + R) and (a + R, b + R), whose linear functionals give the nearest camera
// distance (auto_camera.cpp). A linear functional's maximum over a point set, and a slope's
// extreme seen from a point outside it, are reached at a vertex of the set's convex hull; so when
// the samples reach kCap, those whose eight points (four per plane) are all inside their set's
// hull are dropped, and the camera does not change. Motion whose outline has more than kCap / 2
// extreme points (a body circling for a very long run) is then framed by the box of all its
// spheres instead, which holds them all, and boxed() says so.
#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace tumble::app {

// The camera's axes: r to the right and u up on screen, d from the target towards the camera.
struct ViewAxes {
    glm::dvec3 r, u, d;
};

struct SweptSample {
    glm::dvec3 x;
    double radius;
};

class SweptSpheres {
  public:
    static constexpr std::size_t kCap = std::size_t{1} << 16; // 2 MB of samples

    explicit SweptSpheres(const ViewAxes& axes, std::size_t cap = kCap);

    void add(const glm::dvec3& x, double radius);

    const std::vector<SweptSample>& samples() const { return samples_; }
    // The box of every centre added (kept whole: the fit starts from its middle).
    glm::dvec3 lo() const { return lo_; }
    glm::dvec3 hi() const { return hi_; }
    bool empty() const { return samples_.empty(); }
    bool boxed() const { return boxed_; } // framed by the spheres' box (see above)

  private:
    void prune();

    ViewAxes axes_;
    std::size_t cap_;
    std::vector<SweptSample> samples_;
    glm::dvec3 lo_, hi_;
    double largest_radius_ = 0.0;
    bool boxed_ = false;
};

} // namespace tumble::app
