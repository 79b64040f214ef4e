#pragma once
// sin and cos of one angle together, for the kinematics and dynamics hot paths (the tips of the
// tracking statistics, the arm's forward kinematics, the rigid-body plant: about 15 angles per
// 1 ms step of a simulated cut). glibc's sin and cos cost ~35 ns a pair on these machines; this
// costs ~20 ns with the same accuracy for the angles a machine has (within 2.5e-16 absolute
// for |x| <= 1e5 rad, tests/core/sin_cos_test.cpp), and falls back to the library beyond.
//
// Method: Cody-Waite reduction by pi/2 (pi/2 in three parts, exact products for |q| < 2^26),
// then Cephes' minimax polynomials for sin and cos on [-pi/4, pi/4], the quadrant choosing the
// pair's order and signs. Deterministic: no dependence on the library's version.
#include <cmath>

namespace cutcell {

inline void sinCos(double x, double& s, double& c) {
    if (!(std::fabs(x) <= 1e5)) { // large or NaN: the library's reduction
        s = std::sin(x);
        c = std::cos(x);
        return;
    }
    // Round x * 2 / pi to the nearest integer: adding 1.5 * 2^52 leaves no fraction bits.
    constexpr double kRound = 6755399441055744.0;
    const double q = (x * 0.63661977236758134308 + kRound) - kRound;
    constexpr double kPio2a = 1.57079632673412561417e0, kPio2b = 6.07710050650619224932e-11,
                     kPio2c = 2.02226624879595063154e-21;
    const double r = ((x - q * kPio2a) - q * kPio2b) - q * kPio2c;
    const double z = r * r;
    const double sr =
        r +
        r * z *
            (-1.66666666666666307295e-1 +
             z * (8.33333333332211858878e-3 +
                  z * (-1.98412698295895385996e-4 +
                       z * (2.75573136213857245213e-6 +
                            z * (-2.50507477628578072866e-8 + z * 1.58962301576546568060e-10)))));
    const double cr =
        1.0 - 0.5 * z +
        z * z *
            (4.16666666666665929218e-2 +
             z * (-1.38888888888730564116e-3 +
                  z * (2.48015872888517045348e-5 +
                       z * (-2.75573141792967388112e-7 +
                            z * (2.08757008419747316778e-9 + z * -1.13585365213876817300e-11)))));
    switch (static_cast<long>(q) & 3) {
    case 0:
        s = sr;
        c = cr;
        break;
    case 1:
        s = cr;
        c = -sr;
        break;
    case 2:
        s = -sr;
        c = -cr;
        break;
    default:
        s = -cr;
        c = sr;
        break;
    }
}

} // namespace cutcell
