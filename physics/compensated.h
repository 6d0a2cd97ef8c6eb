#pragma once
// Compensated (Kahan 1965) summation of the position, x += dx each step.
//
// A step adds dx = h v to x. When dx is much smaller than x, the sum x + dx is rounded to the
// spacing of x (one ulp), and the bits of dx below it are lost; summed naively the loss grows by up
// to half an ulp of |x| every step, whatever the step. With h = 1e-7 s and |v| = 0.3 m/s 1e6 steps
// lose 1.2e-10 m at |x| = 3 m, and at |x| = 1e6 m every increment (3e-8 m) is rounded to a multiple
// of 1.2e-10 m, a relative error of 0.2% per step. Kahan's method keeps the lost low-order part in
// a carry and feeds it back into the next increment:
//   y = dx - c,   t = x + y,   c = (t - x) - y,   x = t
// so that the error of x stays about one ulp for any number of steps (Higham, "Accuracy and
// Stability of Numerical Algorithms", 2002, section 4.3). Measured in
// tests/physics/extremes_test.cpp. It relies on IEEE arithmetic being kept as written: Tumble
// builds with -ffp-contract=off and never -ffast-math, which would cancel (t - x) - y to zero.
// x itself is always the best estimate (the carry is below one ulp of x), so everything that reads
// x (diagnostics, contacts, the renderer) reads it as before. Code that sets x outright (a
// teleport, a contact correction) may leave the carry as it is: it is below one ulp of x.
#include "physics/math.h"

namespace tumble::physics {

inline void add_compensated(Vec3& x, Vec3& carry, const Vec3& dx) {
    const Vec3 y = dx - carry;
    const Vec3 t = x + y;
    carry = (t - x) - y;
    x = t;
}

} // namespace tumble::physics
