#pragma once
// Closest points on segments (Ericson, Real-Time Collision Detection, 5.1.2 and 5.1.9), shared by
// the narrow-phase files.
#include "physics/math.h"

#include <algorithm>

namespace tumble::physics {

// Closest point to p on segment [a, b]: a + t (b - a), t = clamp((p - a).d / d.d, 0, 1).
inline Vec3 closest_on_segment(const Vec3& a, const Vec3& b, const Vec3& p) {
    const Vec3 d = b - a;
    const double dd = d.squaredNorm();
    const double t = dd > 0.0 ? std::clamp((p - a).dot(d) / dd, 0.0, 1.0) : 0.0;
    return a + t * d;
}

// Closest points pa on [a0, a1] and pb on [b0, b1]. Minimising |a0 + s da - b0 - t db|^2 gives
// s = (ab br - ar bb) / (aa bb - ab^2) for the infinite lines, clamped to [0, 1]; then
// t = (ab s + br) / bb, and if t leaves [0, 1] it is clamped and s recomputed for that t.
inline void closest_on_segments(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                                Vec3& pa, Vec3& pb) {
    const Vec3 da = a1 - a0, db = b1 - b0, r = a0 - b0;
    const double aa = da.squaredNorm(), bb = db.squaredNorm(), ab = da.dot(db);
    const double ar = da.dot(r), br = db.dot(r);
    const double denom = aa * bb - ab * ab;
    double s = denom > 1e-12 * aa * bb ? std::clamp((ab * br - ar * bb) / denom, 0.0, 1.0) : 0.0;
    double t = bb > 0.0 ? (ab * s + br) / bb : 0.0;
    if (t < 0.0 || t > 1.0) {
        t = std::clamp(t, 0.0, 1.0);
        s = aa > 0.0 ? std::clamp((ab * t - ar) / aa, 0.0, 1.0) : 0.0;
    }
    pa = a0 + s * da;
    pb = b0 + t * db;
}

} // namespace tumble::physics
