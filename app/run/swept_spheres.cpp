#include "app/run/swept_spheres.h"
#include "physics/math.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::app {
namespace {

using physics::kInf;

struct Point {
    double a, b;
    std::size_t sample;
};

// z of (p1 - p0) x (p2 - p0).
double cross(const Point& p0, const Point& p1, const Point& p2) {
    return (p1.a - p0.a) * (p2.b - p0.b) - (p1.b - p0.b) * (p2.a - p0.a);
}

// Marks the samples owning a vertex of the convex hull of `points` (Andrew's monotone chain).
// Points on the hull's edges, or within rounding of them, count as vertices: dropping a point
// is safe only when it is clearly inside.
void mark_hull(std::vector<Point>& points, std::vector<char>& keep) {
    std::sort(points.begin(), points.end(), [](const Point& p, const Point& q) {
        return p.a < q.a || (p.a == q.a && p.b < q.b);
    });
    double scale = 0.0;
    for (const Point& p : points) scale = std::max({scale, std::abs(p.a), std::abs(p.b)});
    const double eps = 1e-9 * scale * scale;
    std::vector<Point> chain;
    for (int pass = 0; pass < 2; ++pass) { // lower hull, then upper
        chain.clear();
        for (const Point& p : points) {
            while (chain.size() >= 2 && cross(chain[chain.size() - 2], chain.back(), p) < -eps)
                chain.pop_back();
            chain.push_back(p);
        }
        for (const Point& p : chain) keep[p.sample] = 1;
        std::reverse(points.begin(), points.end());
    }
}

} // namespace

SweptSpheres::SweptSpheres(const ViewAxes& axes, std::size_t cap)
    : axes_(axes), cap_(std::max<std::size_t>(cap, 16)), lo_(kInf), hi_(-kInf) {}

void SweptSpheres::add(const glm::dvec3& x, double radius) {
    lo_ = glm::min(lo_, x), hi_ = glm::max(hi_, x);
    largest_radius_ = std::max(largest_radius_, radius);
    samples_.push_back({x, radius});
    if (samples_.size() >= cap_) prune();
}

void SweptSpheres::prune() {
    std::vector<char> keep(samples_.size(), 0);
    std::vector<Point> points(samples_.size());
    for (const glm::dvec3& axis : {axes_.r, axes_.u})
        for (int side : {-1, 1})
            for (int lift : {0, 1}) {
                for (std::size_t i = 0; i < samples_.size(); ++i) {
                    const SweptSample& s = samples_[i];
                    points[i] = {glm::dot(s.x, axis) + side * s.radius,
                                 glm::dot(s.x, axes_.d) + lift * s.radius, i};
                }
                mark_hull(points, keep);
            }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < samples_.size(); ++i)
        if (keep[i]) samples_[kept++] = samples_[i];
    samples_.resize(kept);
    if (samples_.size() <= cap_ / 2) return;
    // An outline of too many extreme points: its corners' box, grown by the largest radius,
    // holds every sphere so far.
    boxed_ = true;
    samples_.clear();
    for (int c = 0; c < 8; ++c)
        samples_.push_back(
            {glm::dvec3(c & 1 ? hi_.x : lo_.x, c & 2 ? hi_.y : lo_.y, c & 4 ? hi_.z : lo_.z),
             largest_radius_});
}

} // namespace tumble::app
