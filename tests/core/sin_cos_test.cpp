// sinCos (core/common/sin_cos.h) against the long-double library: the absolute error over the
// angles a machine has, at the multiples of pi/2 where the reduction is hardest, and the
// library's own result beyond |x| = 1e5 rad and for NaN / Inf.
#include "core/common/sin_cos.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

using cutcell::sinCos;

namespace {

double error(double x) {
    double s = 0, c = 0;
    sinCos(x, s, c);
    const long double ls = sinl(static_cast<long double>(x)),
                      lc = cosl(static_cast<long double>(x));
    return static_cast<double>(std::max(fabsl(s - ls), fabsl(c - lc)));
}

} // namespace

TEST(SinCos, MatchesTheLibraryToAFewUlps) {
    std::mt19937_64 rng(11);
    double worst = 0;
    for (const double range : {1.0, 10.0, 1e3, 1e5}) {
        std::uniform_real_distribution<double> u(-range, range);
        for (int i = 0; i < 400000; ++i)
            worst = std::max(worst, error(u(rng)));
    }
    for (int k = -60000; k <= 60000; ++k)
        worst = std::max(worst, error(k * 1.5707963267948966));
    std::printf("sinCos: worst absolute error %.3g\n", worst);
    // glibc's own double sin and cos are within 1 ulp (1.1e-16 near 1).
    EXPECT_LT(worst, 3e-16);
}

TEST(SinCos, BeyondItsRangeItIsTheLibrary) {
    for (const double x : {1e5 + 1, -3e7, 1e300}) {
        double s = 0, c = 0;
        sinCos(x, s, c);
        EXPECT_EQ(s, std::sin(x));
        EXPECT_EQ(c, std::cos(x));
    }
    double s = 0, c = 0;
    sinCos(std::numeric_limits<double>::quiet_NaN(), s, c);
    EXPECT_TRUE(std::isnan(s) && std::isnan(c));
    sinCos(std::numeric_limits<double>::infinity(), s, c);
    EXPECT_TRUE(std::isnan(s) && std::isnan(c));
    sinCos(0.0, s, c);
    EXPECT_EQ(s, 0.0);
    EXPECT_EQ(c, 1.0);
}
