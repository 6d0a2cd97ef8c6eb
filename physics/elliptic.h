#pragma once
// Jacobi's elliptic functions and Carlson's symmetric elliptic integrals in double precision, for
// the exact free rigid body (free_rotation.h). Eigen-free, allocation-free and exception-free: the
// `exact` integrators call them every step.
//
// Parametrised by the complementary parameter mc = 1 - k^2 rather than the modulus k, because the
// free body needs them near k = 1 (close to the separatrix, where the intermediate-axis flips
// happen): k^2 = 1 - 1e-14 cannot be told from 1 once rounded, but mc = 1e-14 is exact, and every
// quantity below is formed from mc without the cancellation 1 - k^2. mc = 0 is the separatrix
// itself, where sn = tanh, cn = dn = sech and K is infinite.
//
// Sources: B. C. Carlson, "Numerical computation of real or complex elliptic integrals", Numer.
// Algorithms 10 (1995) (R_F, R_J, R_C by duplication, DLMF 19.36(i)); R. Bulirsch, "Numerical
// calculation of elliptic integrals and elliptic functions", Numer. Math. 7 (1965) (sn, cn, dn by
// the descending Gauss transformation, DLMF 22.20(ii)). Checked against Boost.Math in long double
// by tests/physics/elliptic_test.cpp.
namespace tumble::physics {

// Each function exists for double (what FreeRotation steps with) and long double (x87's 64-bit
// mantissa, for references; tests/physics/elliptic_test.cpp checks both against Boost).

// R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t + x)(t + y)(t + z)); x, y, z >= 0, at most one zero.
template <class T>
T carlson_rf(T x, T y, T z);

// R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t + p) sqrt((t + x)(t + y)(t + z))); p > 0.
template <class T>
T carlson_rj(T x, T y, T z, T p);

// The arithmetic-geometric mean ladder a_0 = 1, b_0 = sqrt(mc), a_{j+1} = (a_j + b_j) / 2,
// b_{j+1} = sqrt(a_j b_j), run once per parameter and shared by every evaluation of sn, cn, dn
// (and K = pi / (2 a_inf)). Fixed size: it converges quadratically, in at most 12 rungs for any
// positive double mc (measured; the first rungs halve a while b catches up). mc = 0 has no ladder
// (the functions are hyperbolic there).
template <class T>
struct AgmLadder {
    static constexpr int kMaxRungs = 24;
    T mc = 1;
    T a[kMaxRungs] = {}, b[kMaxRungs] = {};
    int rungs = 0; // a[0..rungs-1], b[0..rungs-1] used
    T a_inf = 1;   // the mean, a_{rungs}
};
template <class T>
AgmLadder<T> agm_ladder(T mc); // 0 <= mc <= 1

// K(k) = int_0^{pi/2} dt / sqrt(1 - k^2 sin^2 t) = pi / (2 AGM(1, k')); infinite when mc = 0.
template <class T>
T complete_k(const AgmLadder<T>& ladder);

template <class T>
struct Jacobi {
    T sn, cn, dn;
};
// sn(u | k), cn(u | k), dn(u | k) for any real u, with k^2 = 1 - ladder.mc.
template <class T>
Jacobi<T> jacobi(T u, const AgmLadder<T>& ladder);

} // namespace tumble::physics
