// Elliptic functions and integrals (elliptic.h). Each routine states the identity it iterates.
#include "physics/elliptic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tumble::physics {
namespace {

// R_C(1, 1 + e) = atan(sqrt(e)) / sqrt(e) for e > 0, atanh(sqrt(-e)) / sqrt(-e) for -1 < e < 0
// (DLMF 19.2.18-19): the degenerate R_F(x, y, y) that the R_J recurrence sums.
template <class T>
T rc_one(T e) {
    // Small e (every rung after the first few): the series 1 - e/3 + e^2/5 - ..., whose next term
    // is below 1e-22 for |e| < 1e-3, instead of an inverse tangent.
    if (std::abs(e) < T(1e-3)) {
        T sum = 0;
        for (int j = 7; j >= 0; --j) sum = T(j % 2 ? -1 : 1) / T(2 * j + 1) + e * sum;
        return sum;
    }
    if (e > 0) return std::atan(std::sqrt(e)) / std::sqrt(e);
    return std::atanh(std::sqrt(-e)) / std::sqrt(-e);
}

// Carlson's stopping rule: after n duplications the relative deviations of the arguments from
// their mean A_n are at most 4^-n Q / |A_n|, and the truncated series below errs by about the
// sixth power of that. Q = (3 r)^(-1/6) max |A_0 - x_j| for R_F and (r / 4)^(-1/6) for R_J, with
// r the relative error wanted (Carlson 1995, section 2): r = 1e-20, below long double's 1.1e-19
// (the truncation error has one sign: a bias if it were not negligible).
constexpr double kRfSpread = 1789.0; // (3e-20)^(-1/6)
constexpr double kRjSpread = 2567.0; // (2.5e-21)^(-1/6)

} // namespace

// Duplication (DLMF 19.26.18): R_F(x, y, z) = R_F((x + l)/4, (y + l)/4, (z + l)/4) with
// l = sqrt(x y) + sqrt(x z) + sqrt(y z), until the three arguments agree; then the series in the
// elementary symmetric functions E2, E3 of the scaled deviations X = (A_0 - x) / (4^n A_n), ...
// (DLMF 19.36.1).
// R_F and R_J diverge when two of x, y, z vanish; the duplication would then never converge.
template <class T>
bool two_zero(T x, T y, T z) {
    return (x == 0) + (y == 0) + (z == 0) >= 2;
}

// Duplications at most: each divides the arguments' relative spread by 4, and the spread starts
// below 4 (R_F) or 6 (R_J) times Carlson's Q / |A_0|, so 40 is far more than any input needs.
constexpr int kMaxDuplications = 40;

template <class T>
T carlson_rf(T x, T y, T z) {
    if (two_zero(x, y, z)) return std::numeric_limits<T>::infinity();
    const T a0 = (x + y + z) / 3;
    const T q = T(kRfSpread) * std::max({std::abs(a0 - x), std::abs(a0 - y), std::abs(a0 - z)});
    T xn = x, yn = y, zn = z, a = a0, scale = 1; // scale = 4^-n
    for (int n = 0; n < kMaxDuplications && scale * q >= std::abs(a); ++n) {
        const T sx = std::sqrt(xn), sy = std::sqrt(yn), sz = std::sqrt(zn);
        const T l = sx * sy + sx * sz + sy * sz;
        xn = (xn + l) / 4, yn = (yn + l) / 4, zn = (zn + l) / 4, a = (a + l) / 4;
        scale /= 4;
    }
    const T X = (a0 - x) * scale / a, Y = (a0 - y) * scale / a, Z = -(X + Y);
    const T e2 = X * Y - Z * Z, e3 = X * Y * Z;
    return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / std::sqrt(a);
}

// Duplication of R_J (DLMF 19.26.20 with the sum of R_C terms written as in Carlson 1995):
//   R_J = 4^-n A_n^-3/2 (1 - 3 E2/14 + E3/6 + 9 E2^2/88 - 3 E4/22 - 9 E2 E3/52 + 3 E5/26)
//         + 6 sum_{m<n} 4^-m R_C(1, 1 + e_m) / d_m,
// d_m = (sqrt p_m + sqrt x_m)(sqrt p_m + sqrt y_m)(sqrt p_m + sqrt z_m),
// e_m = 4^-3m (p - x)(p - y)(p - z) / d_m^2, and X, Y, Z as for R_F, P = -(X + Y + Z) / 2,
// E2 = XY + XZ + YZ - 3P^2, E3 = XYZ + 2 E2 P + 4 P^3, E4 = (2 XYZ + E2 P + 3 P^3) P,
// E5 = XYZ P^2 (DLMF 19.36.2).
template <class T>
T carlson_rj(T x, T y, T z, T p) {
    if (two_zero(x, y, z)) return std::numeric_limits<T>::infinity();
    const T a0 = (x + y + z + 2 * p) / 5;
    const T delta = (p - x) * (p - y) * (p - z);
    const T q = T(kRjSpread) *
                std::max({std::abs(a0 - x), std::abs(a0 - y), std::abs(a0 - z), std::abs(a0 - p)});
    T xn = x, yn = y, zn = z, pn = p, a = a0, scale = 1, sum = 0;
    for (int n = 0; n < kMaxDuplications && scale * q >= std::abs(a); ++n) {
        const T sx = std::sqrt(xn), sy = std::sqrt(yn), sz = std::sqrt(zn), sp = std::sqrt(pn);
        const T l = sx * sy + sx * sz + sy * sz;
        const T d = (sp + sx) * (sp + sy) * (sp + sz);
        const T e = scale * scale * scale * delta / (d * d);
        sum += scale * rc_one(e) / d;
        xn = (xn + l) / 4, yn = (yn + l) / 4, zn = (zn + l) / 4, pn = (pn + l) / 4;
        a = (a + l) / 4;
        scale /= 4;
    }
    const T X = (a0 - x) * scale / a, Y = (a0 - y) * scale / a, Z = (a0 - z) * scale / a;
    const T P = -(X + Y + Z) / 2;
    const T xyz = X * Y * Z, p2 = P * P;
    const T e2 = X * Y + X * Z + Y * Z - 3 * p2;
    const T e3 = xyz + 2 * e2 * P + 4 * p2 * P;
    const T e4 = (2 * xyz + e2 * P + 3 * p2 * P) * P;
    const T e5 = xyz * p2;
    const T series =
        1 - 3 * e2 / 14 + e3 / 6 + 9 * e2 * e2 / 88 - 3 * e4 / 22 - 9 * e2 * e3 / 52 + 3 * e5 / 26;
    return scale * series / (a * std::sqrt(a)) + 6 * sum;
}

// a_0 = 1, b_0 = k' = sqrt(mc); the rung j is kept until |a_j - b_j| <= 1e-10 a_j. The modulus left
// above the last rung is then k_N ~ (a - b) / 2a <= 5e-11, and treating its functions as
// trigonometric errs by O(k_N^2) ~ 3e-21 (quadratic convergence: the gap is squared each rung).
// (Bulirsch's 1e-8 would err by 3e-17 with one sign: a bias in long double.)
template <class T>
AgmLadder<T> agm_ladder(T mc) {
    AgmLadder<T> l;
    l.mc = mc;
    if (mc == 0) return l; // the separatrix: jacobi() and complete_k() do not climb
    T a = 1, b = std::sqrt(mc);
    for (;;) {
        l.a[l.rungs] = a;
        l.b[l.rungs] = b;
        ++l.rungs;
        const T next = (a + b) / 2;
        if (std::abs(a - b) <= T(1e-10) * a || l.rungs == AgmLadder<T>::kMaxRungs) {
            l.a_inf = next;
            return l;
        }
        b = std::sqrt(a * b);
        a = next;
    }
}

template <class T>
T complete_k(const AgmLadder<T>& l) {
    if (l.mc == 0) return std::numeric_limits<T>::infinity();
    return std::numbers::pi_v<T> / (2 * l.a_inf);
}

// Bulirsch's descending Gauss transformation. At the top of the ladder the modulus is negligible
// and the functions are trigonometric: sn = sin(a_inf u), cn = cos(a_inf u). Going down, each rung
// j maps the ratio c = cn / sn and dn of modulus k_{j+1} to those of k_j (DLMF 22.7.1-3 written
// for the ratio, which needs no inverse sine and keeps its accuracy as k -> 1); at the bottom
// sn = +-1 / sqrt(1 + c^2), cn = c sn, the sign of sn being that of sin(a_inf u) (the
// transformation keeps the sign of sn at every rung).
template <class T>
Jacobi<T> jacobi(T u, const AgmLadder<T>& l) {
    if (l.mc == 0) { // k = 1: the separatrix
        const T sech = 1 / std::cosh(u);
        return {std::tanh(u), sech, sech};
    }
    const T phi = l.a_inf * u;
    const T s = std::sin(phi), c = std::cos(phi);
    // Within 1e-150 of a zero of sn (u = 2 K j to that accuracy): sn = 0, cn = +-1, dn = 1 up to
    // 1e-150, and the ratio below would overflow.
    if (std::abs(s) < T(1e-150)) return {0, c, 1};
    T ratio = c / s, t = l.a_inf * ratio, dn = 1;
    for (int j = l.rungs - 1; j >= 0; --j) {
        ratio *= t;
        t *= dn;
        dn = (l.b[j] + ratio) / (l.a[j] + ratio);
        ratio = t / l.a[j];
    }
    const T sn = std::copysign(1 / std::sqrt(1 + t * t), s);
    return {sn, t * sn, dn};
}

template double carlson_rf(double, double, double);
template long double carlson_rf(long double, long double, long double);
template double carlson_rj(double, double, double, double);
template long double carlson_rj(long double, long double, long double, long double);
template AgmLadder<double> agm_ladder(double);
template AgmLadder<long double> agm_ladder(long double);
template double complete_k(const AgmLadder<double>&);
template long double complete_k(const AgmLadder<long double>&);
template Jacobi<double> jacobi(double, const AgmLadder<double>&);
template Jacobi<long double> jacobi(long double, const AgmLadder<long double>&);

} // namespace tumble::physics
