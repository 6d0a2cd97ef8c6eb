// physics' elliptic functions (physics/elliptic.h) against Boost.Math evaluated in long double (an
// independent implementation, 11 more bits), against the expansions about k = 1 (DLMF 22.10.ii,
// 19.12.1) where even long double cannot hold k, and against their own identities.
#include "physics/elliptic.h"

#include "support/measured.h"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tumble::physics {
namespace {

double rel(double a, long double ref) {
    return static_cast<double>(std::fabs((a - ref) / ref));
}

// Arguments spanning the ones the free body uses (cn^2, dn^2 in [0, 1], 1, and p = 1 - n sn^2
// up to ~1e3), a zero argument, and widely different scales.
const std::vector<std::vector<double>> kArgs = {
    {0.0, 1e-14, 1.0, 1.0},  {0.0, 0.5, 1.0, 2.0},    {0.3, 0.7, 1.0, 1.5},
    {1e-3, 2e-3, 1.0, 40.0}, {0.9, 0.95, 1.0, 1e3},   {1e-12, 1e-10, 1.0, 3.0},
    {2.0, 3.0, 4.0, 5.0},    {1e-20, 0.3, 1.0, 1.01}, {0.25, 0.25, 1.0, 7.0},
};

TEST(Elliptic, CarlsonIntegralsMatchBoostInLongDouble) {
    double worst_rf = 0.0, worst_rj = 0.0;
    for (const auto& a : kArgs) {
        const long double rf = boost::math::ellint_rf<long double>(a[0], a[1], a[2]);
        const long double rj = boost::math::ellint_rj<long double>(a[0], a[1], a[2], a[3]);
        worst_rf = std::max(worst_rf, rel(carlson_rf(a[0], a[1], a[2]), rf));
        worst_rj = std::max(worst_rj, rel(carlson_rj(a[0], a[1], a[2], a[3]), rj));
    }
    // About one ulp: measured 2.9e-16 and 1.8e-16.
    TUMBLE_MEASURED(worst_rf, 1e-15);
    TUMBLE_MEASURED(worst_rj, 2e-15);
    EXPECT_LT(worst_rf, 1e-15);
    EXPECT_LT(worst_rj, 2e-15);
}

// Parameters mc = 1 - k^2 from a circle (k = 0) to 1e-16 from the separatrix. Long double holds
// k = sqrt(1 - mc) to 5e-20, so mc only to 1e-19 absolute: Boost's answer is a reference for
// |u| < K at every mc here (the range the free body's steps use), but over several periods only
// while 1e-19 / mc is negligible (mc >= 1e-4): beyond K, sn moves with K, whose own error from
// Boost's k alone is 1e-19 / (2 mc), 5e-11 at mc = 1e-9.
const double kParameters[] = {1.0, 0.75, 0.3, 1e-2, 1.4e-4, 1e-6, 1e-9, 1e-12, 1e-16};

TEST(Elliptic, JacobiFunctionsMatchBoostInLongDouble) {
    double worst = 0.0, worst_k = 0.0;
    for (double mc : kParameters) {
        if (mc < 1e-12) continue; // the next test's reference
        const AgmLadder l = agm_ladder(mc);
        const long double k = std::sqrt(1.0L - static_cast<long double>(mc));
        const double K = complete_k(l);
        if (mc >= 1e-4) worst_k = std::max(worst_k, rel(K, boost::math::ellint_1(k)));
        for (int j = -60; j <= 60; ++j) {
            // Off the grid points K j: over [-6.8 K, 6.8 K], or [-0.99 K, 0.99 K].
            const double u = mc >= 1e-4 ? 0.1 * j * K + 0.013 * j : 0.0165 * j * K;
            long double cn = 0, dn = 0;
            const long double sn =
                boost::math::jacobi_elliptic(k, static_cast<long double>(u), &cn, &dn);
            const Jacobi e = jacobi(u, l);
            // Absolute: the functions are O(1), and near their zeros a relative error means
            // nothing; scaled by 1 + |u| for the argument's own rounding (d sn / du <= 1).
            const double err = std::max({std::fabs(e.sn - static_cast<double>(sn)),
                                         std::fabs(e.cn - static_cast<double>(cn)),
                                         std::fabs(e.dn - static_cast<double>(dn))}) /
                               (1.0 + std::abs(u));
            worst = std::max(worst, err);
            EXPECT_LT(err, 1e-15) << "mc = " << mc << " u = " << u;
        }
    }
    TUMBLE_MEASURED(worst, 1e-15);
    TUMBLE_MEASURED(worst_k, 1e-15);
    EXPECT_LT(worst_k, 1e-15);
}

// Periodicity over many periods with the ladder's own K: sn(u + 2K) = -sn(u), cn(u + 2K) = -cn(u),
// dn(u + 2K) = dn(u), at every parameter (the check Boost cannot make below mc ~ 1e-4).
TEST(Elliptic, JacobiFunctionsArePeriodicWithTheirOwnK) {
    double worst = 0.0;
    for (double mc : kParameters) {
        const AgmLadder l = agm_ladder(mc);
        const double K = complete_k(l);
        for (int j = -5; j <= 5; ++j)
            for (double r : {-0.93, -0.4, 0.0, 0.31, 0.77, 0.999}) {
                const double u = 2.0 * K * j + r * K;
                const Jacobi a = jacobi(u, l), b = jacobi(r * K, l);
                const double sign = j % 2 == 0 ? 1.0 : -1.0;
                const double err =
                    std::max({std::fabs(a.sn - sign * b.sn), std::fabs(a.cn - sign * b.cn),
                              std::fabs(a.dn - b.dn)}) /
                    (1.0 + std::abs(u));
                worst = std::max(worst, err);
            }
    }
    // The rounding of u = 2 K j + r K itself moves sn by ~|u| eps: measured 2.1e-16 per unit u.
    TUMBLE_MEASURED(worst, 4e-16);
    EXPECT_LT(worst, 4e-16);
}

// Below mc ~ 1e-12 long double's k no longer pins mc down; below 1e-16 no floating-point k can be
// told from 1. The reference is the expansion in
// k'^2 = mc about the separatrix (DLMF 22.10.8-10), whose O(mc^2 e^2|u| / 64) remainder is kept
// below 1e-17 here (|u| <= 3.1 at mc = 1e-9, 6 at 1e-12, 15 below):
//   sn = tanh u + mc/4 (sinh u cosh u - u) sech^2 u
//   cn = sech u - mc/4 (sinh u cosh u - u) tanh u sech u
//   dn = sech u + mc/4 (sinh u cosh u + u) tanh u sech u
// and K = ln(4 / k') + mc/4 (ln(4 / k') - 1) + O(mc^2 ln mc) (DLMF 19.12.1).
TEST(Elliptic, NearTheSeparatrixFollowTheExpansionAboutKEqualsOne) {
    double worst = 0.0, worst_k = 0.0;
    for (double mc : {1e-9, 1e-12, 1e-16, 1e-18, 1e-24, 1e-40, 1e-300, 0.0}) {
        const AgmLadder l = agm_ladder(mc);
        EXPECT_LE(l.rungs, 12) << mc; // the ladder converged (measured: 12 rungs at 1e-300)
        if (mc > 0.0) {
            const double lk = std::log(4.0 / std::sqrt(mc));
            worst_k = std::max(worst_k, rel(complete_k(l), lk + mc / 4.0 * (lk - 1.0)));
        } else {
            EXPECT_TRUE(std::isinf(complete_k(l)));
        }
        for (double u : {-12.0, -3.1, -0.4, 0.0, 0.25, 1.7, 6.0, 15.0}) {
            if (std::abs(u) > (mc >= 1e-9 ? 3.1 : mc >= 1e-12 ? 6.0 : 15.0)) continue;
            const double t = std::tanh(u), s = 1.0 / std::cosh(u), g = std::sinh(u) * std::cosh(u);
            const Jacobi e = jacobi(u, l);
            const double err = std::max({std::fabs(e.sn - (t + mc / 4.0 * (g - u) * s * s)),
                                         std::fabs(e.cn - (s - mc / 4.0 * (g - u) * t * s)),
                                         std::fabs(e.dn - (s + mc / 4.0 * (g + u) * t * s))});
            worst = std::max(worst, err);
            EXPECT_LT(err, 1e-15) << "mc = " << mc << " u = " << u;
        }
    }
    TUMBLE_MEASURED(worst, 1e-15);
    TUMBLE_MEASURED(worst_k, 1e-15);
    EXPECT_LT(worst_k, 1e-15);
}

TEST(Elliptic, DivergentIntegralsAreInfiniteNotEndless) {
    // Two zero arguments make R_F and R_J diverge (their duplication would never converge);
    // one zero is the usual complete case, K = R_F(0, k'^2, 1).
    EXPECT_TRUE(std::isinf(carlson_rf(0.0, 0.0, 1.0)));
    EXPECT_TRUE(std::isinf(carlson_rj(0.0, 0.0, 1.0, 2.0)));
    EXPECT_TRUE(std::isfinite(carlson_rf(0.0, 0.5, 1.0)));
    EXPECT_NEAR(carlson_rf(0.0, 0.75, 1.0), complete_k(agm_ladder(0.75)), 1e-15);
}

TEST(Elliptic, IdentitiesHoldToRoundOff) {
    // sn^2 + cn^2 = 1 and dn^2 + k^2 sn^2 = 1 (dn^2 - mc sn^2 = cn^2 without cancellation),
    // and sn(K) = 1, cn(K) = 0, dn(K) = k'.
    double worst = 0.0;
    for (double mc : kParameters) {
        const AgmLadder l = agm_ladder(mc);
        for (double u = -7.0; u <= 7.0; u += 0.37) {
            const Jacobi e = jacobi(u, l);
            worst = std::max({worst, std::fabs(e.sn * e.sn + e.cn * e.cn - 1.0),
                              std::fabs(e.dn * e.dn - mc * e.sn * e.sn - e.cn * e.cn)});
        }
        const Jacobi at_k = jacobi(complete_k(l), l);
        EXPECT_NEAR(at_k.sn, 1.0, 1e-15) << mc;
        EXPECT_NEAR(at_k.cn, 0.0, 1e-15) << mc;
        EXPECT_NEAR(at_k.dn, std::sqrt(mc), 1e-15) << mc;
    }
    TUMBLE_MEASURED(worst, 1e-15);
    EXPECT_LT(worst, 1e-15);
}

TEST(Elliptic, LongDoubleVersionsMatchFiftyDigitsToTheirPrecision) {
    // The long double instantiations (for references) against Boost in 50 decimal digits
    // (cpp_bin_float_50; Boost's own long double sn, cn, dn err by 2.7e-17 near K): a few of long
    // double's ulps (1.1e-19). Measured 2.1e-19 (R_F, R_J) and 1.6e-19 (sn, cn, dn).
    using F = boost::multiprecision::cpp_bin_float_50;
    double worst_carlson = 0.0, worst_jacobi = 0.0;
    for (const auto& a : kArgs) {
        const long double x = a[0], y = a[1], z = a[2], p = a[3];
        const F rf = boost::math::ellint_rf(F(x), F(y), F(z));
        const F rj = boost::math::ellint_rj(F(x), F(y), F(z), F(p));
        worst_carlson = std::max({worst_carlson, double(abs(F(carlson_rf(x, y, z)) / rf - 1)),
                                  double(abs(F(carlson_rj(x, y, z, p)) / rj - 1))});
    }
    for (long double mc : {1.0L, 0.3L, 1e-2L, 1e-4L}) {
        const AgmLadder<long double> l = agm_ladder(mc);
        const long double K = complete_k(l);
        const F k = sqrt(1 - F(mc));
        for (int j = -20; j <= 20; ++j) {
            const long double u = 0.999L * j * K / 20;
            F cn = 0, dn = 0;
            const F sn = boost::math::jacobi_elliptic(k, F(u), &cn, &dn);
            const Jacobi<long double> e = jacobi(u, l);
            worst_jacobi = std::max({worst_jacobi, double(abs(F(e.sn) - sn)),
                                     double(abs(F(e.cn) - cn)), double(abs(F(e.dn) - dn))});
        }
    }
    TUMBLE_MEASURED(worst_carlson, 1e-18);
    TUMBLE_MEASURED(worst_jacobi, 1e-18);
    EXPECT_LT(worst_carlson, 1e-18);
    EXPECT_LT(worst_jacobi, 1e-18);
}

} // namespace
} // namespace tumble::physics
